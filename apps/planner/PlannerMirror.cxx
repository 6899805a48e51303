// latticekit-planner: the mirror image (o, O): the bone's plane of symmetry, the
// mirror drawn over it, and how far the moved segment is from it.
#include "planner/Planner.h"
#include "planner/PlannerShared.h"

#include "common/AppSupport.h"

#include "vtkLKPolyDataConversion.h"
#include "vtkLKSymmetryPlaneFilter.h"

#include "latticekit/ClosestPointTree.h"
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

namespace
{
/// The corners of the plane (origin, unit normal) over a box: two axes in
/// it (the one nearest z first, so a mid-sagittal plane stands upright),
/// the box's corners projected onto them, and 5 % more on each side.
vtkSmartPointer<vtkPoints> planeCorners(
  const std::array<double, 3>& origin, const std::array<double, 3>& normal, const double bounds[6])
{
  std::array<double, 3> u =
    std::abs(normal[2]) < 0.9 ? std::array<double, 3>{ 0, 0, 1 } : std::array<double, 3>{ 0, 1, 0 };
  const double along = vtkMath::Dot(u.data(), normal.data());
  for (int k = 0; k < 3; ++k)
    u[k] -= along * normal[k];
  vtkMath::Normalize(u.data());
  std::array<double, 3> v;
  vtkMath::Cross(normal.data(), u.data(), v.data());
  double low[2] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX }, high[2] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (int corner = 0; corner < 8; ++corner)
  {
    const double x[3] = { bounds[corner & 1] - origin[0], bounds[2 + ((corner >> 1) & 1)] - origin[1],
      bounds[4 + ((corner >> 2) & 1)] - origin[2] };
    const double a[2] = { vtkMath::Dot(x, u.data()), vtkMath::Dot(x, v.data()) };
    for (int k = 0; k < 2; ++k)
    {
      low[k] = std::min(low[k], a[k]);
      high[k] = std::max(high[k], a[k]);
    }
  }
  const double margin[2] = { 0.05 * (high[0] - low[0]), 0.05 * (high[1] - low[1]) };
  auto corners = vtkSmartPointer<vtkPoints>::New();
  for (const auto& [cu, cv] : { std::make_pair(0, 0), std::make_pair(1, 0), std::make_pair(1, 1), std::make_pair(0, 1) })
  {
    const double a = cu ? high[0] + margin[0] : low[0] - margin[0];
    const double b = cv ? high[1] + margin[1] : low[1] - margin[1];
    corners->InsertNextPoint(
      origin[0] + a * u[0] + b * v[0], origin[1] + a * u[1] + b * v[1], origin[2] + a * u[2] + b * v[2]);
  }
  return corners;
}
} // namespace

const Planner::MirrorImage& Planner::mirrorImage()
{
  if (mirror.made && mirror.madeWith == session.mirrorPlane)
    return mirror;
  mirror = MirrorImage();
  mirror.made = true;
  mirror.madeWith = session.mirrorPlane;
  mirrorFitPiece = nullptr; // the segment's distance before its move, anew
  vtkNew<vtkLKSymmetryPlaneFilter> symmetry;
  symmetry->SetInputData(facesOnly(bone));
  // The patient's left-right axis: x in LPS and RAS alike (a CT's patient
  // lies along z, facing y).
  symmetry->SetInitialNormal(1.0, 0.0, 0.0);
  if (!session.mirrorPlane.empty())
  {
    // The plane the surgeon set through three points (checked when read or
    // clicked).
    std::array<double, 3> origin, normal;
    std::string why;
    if (!lkplanner::planeThrough(session.mirrorPlane, origin, normal, why))
    {
      mirror.error = why;
      return mirror;
    }
    symmetry->FitPlaneOff();
    symmetry->SetGivenPlaneOrigin(origin.data());
    symmetry->SetGivenPlaneNormal(normal.data());
  }
  const int before = lkapp::errorCount();
  symmetry->Update();
  if (symmetry->GetOutput()->GetNumberOfPolys() == 0)
  {
    mirror.error = lkapp::errorCount() > before ? lkapp::errorsSince(before) : std::string("no mirror image was made");
    return mirror;
  }
  mirror.surface = vtkSmartPointer<vtkPolyData>::New();
  mirror.surface->ShallowCopy(symmetry->GetOutput());
  symmetry->GetPlaneOrigin(mirror.origin.data());
  symmetry->GetPlaneNormal(mirror.normal.data());
  for (auto* values : { &mirror.origin, &mirror.normal })
    for (double& v : *values)
      v = std::abs(v) < 1e-9 ? 0.0 : v; // rounding's dust (a plane set by clicks), and no "-0.0000"
  mirror.mean = symmetry->GetMeanDistance();
  mirror.largest = symmetry->GetMaximumDistance();
  mirror.kept = symmetry->GetKeptFraction();
  lk::TriangleMesh triangles;
  mirror.error = lkvtk::toTriangleMesh(mirror.surface, triangles);
  try
  {
    if (mirror.error.empty())
      mirror.tree = std::make_shared<const lk::ClosestPointTree>(triangles);
  }
  catch (const std::exception& e)
  {
    mirror.error = e.what();
  }
  if (!mirror.tree)
  {
    mirror.surface = nullptr;
    return mirror;
  }
  vtkPolyDataMapper::SafeDownCast(mirrorActor->GetMapper())->SetInputData(mirror.surface);
  // The plane over the bone's extent: a faint sheet and its outline.
  double bounds[6];
  bone->GetBounds(bounds);
  showSquare(planeCorners(mirror.origin, mirror.normal, bounds), mirrorPlaneActor, mirrorPlaneOutline);
  return mirror;
}

Planner::MirrorFit Planner::mirrorFitOf(const std::array<double, 16>& matrix) const
{
  MirrorFit fit;
  if (!mirror.tree || !hasSegment())
    return fit;
  vtkPolyData* segment = pieces[static_cast<std::size_t>(session.segment)];
  double sum = 0.0;
  lk::ClosestPointTree::Hit hit; // each vertex's hit starts its neighbour's search
  for (std::size_t k = 0; k < mirrorFitVertices.size(); ++k)
  {
    std::array<double, 3> x;
    segment->GetPoint(mirrorFitVertices[k], x.data());
    x = lkapp::placedPoint(matrix, x);
    const lk::Vec3 q(x[0], x[1], x[2]);
    hit = k == 0 ? mirror.tree->closest(q) : mirror.tree->closest(q, hit);
    sum += hit.distance;
    fit.largest = std::max(fit.largest, hit.distance);
  }
  fit.valid = !mirrorFitVertices.empty();
  fit.mean = fit.valid ? sum / static_cast<double>(mirrorFitVertices.size()) : 0.0;
  return fit;
}

void Planner::updateMirrorFit(const std::array<double, 16>& matrix)
{
  segmentToMirror = MirrorFit();
  if (!session.mirror || !mirror.surface || !hasSegment())
    return;
  vtkPolyData* segment = pieces[static_cast<std::size_t>(session.segment)];
  if (segment != mirrorFitPiece || segment->GetMTime() != mirrorFitTime)
  {
    // A piece the drag has not seen: its vertices of the bone's own surface
    // (a cap's lie inside the mirror image, where the cut went through the
    // bone), and its fit where it was cut.
    std::vector<char> onBone(static_cast<std::size_t>(segment->GetNumberOfPoints()), 0);
    vtkDataArray* cap = segment->GetCellData()->GetArray("Cap");
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < segment->GetNumberOfCells(); ++c)
    {
      const int type = segment->GetCellType(c);
      if ((type != VTK_TRIANGLE && type != VTK_POLYGON && type != VTK_QUAD) || (cap && cap->GetTuple1(c) != 0.0))
        continue;
      segment->GetCellPoints(c, ids);
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
        onBone[static_cast<std::size_t>(ids->GetId(k))] = 1;
    }
    mirrorFitVertices.clear();
    for (vtkIdType i = 0; i < segment->GetNumberOfPoints(); ++i)
      if (onBone[static_cast<std::size_t>(i)])
        mirrorFitVertices.push_back(i);
    mirrorFitPiece = segment;
    mirrorFitTime = segment->GetMTime();
    segmentToMirrorBefore = mirrorFitOf(Session().segmentMatrix);
  }
  segmentToMirror = isIdentity(matrix) ? segmentToMirrorBefore : mirrorFitOf(matrix);
}

double Planner::degreesFromX(const std::array<double, 3>& normal)
{
  const double x[3] = { 1.0, 0.0, 0.0 };
  return vtkMath::DegreesFromRadians(vtkMath::AngleBetweenVectors(normal.data(), x));
}

std::string Planner::mirrorText() const
{
  if (!session.mirror)
    return "";
  if (!mirror.surface)
    return "mirror image: none (" + mirror.error + ")\n";
  const double tilt = degreesFromX(mirror.normal);
  char line[600];
  if (mirror.madeWith.empty())
    std::snprintf(line, sizeof line,
      "mirror image: across the bone's plane of symmetry through (%.2f, %.2f, %.2f), normal (%.4f, %.4f, %.4f), "
      "%.1f deg from x; the bone is %.2f mm from it on average, %.2f mm at most; the plane was fitted to %.0f %% of "
      "the bone (the rest lies farther from its mirror)\n",
      mirror.origin[0], mirror.origin[1], mirror.origin[2], mirror.normal[0], mirror.normal[1], mirror.normal[2],
      tilt, mirror.mean, mirror.largest, 100.0 * mirror.kept);
  else
  {
    const auto& p = mirror.madeWith;
    std::snprintf(line, sizeof line,
      "mirror image: across the plane set through (%.2f, %.2f, %.2f), (%.2f, %.2f, %.2f) and (%.2f, %.2f, %.2f), "
      "normal (%.4f, %.4f, %.4f), %.1f deg from x; the bone is %.2f mm from it on average, %.2f mm at most\n",
      p[0][0], p[0][1], p[0][2], p[1][0], p[1][1], p[1][2], p[2][0], p[2][1], p[2][2], mirror.normal[0],
      mirror.normal[1], mirror.normal[2], tilt, mirror.mean, mirror.largest);
  }
  std::string text = line;
  if (segmentToMirror.valid)
  {
    std::snprintf(line, sizeof line,
      "segment and the mirror image: %.2f mm apart on average, %.2f mm at most (%.2f and %.2f before the segment's "
      "move)\n",
      segmentToMirror.mean, segmentToMirror.largest, segmentToMirrorBefore.mean, segmentToMirrorBefore.largest);
    text += line;
  }
  return text;
}

} // namespace lkplanner
