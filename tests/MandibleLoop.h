#pragma once
/// \file MandibleLoop.h
/// The TCIA mandible's bone surface and a closed feature line around a bone
/// surface, shared by the fit and cut tests.

#include "TestSupport.h"
#include "latticekit/EdgePath.h"
#include "latticekit/LatticeSimplification.h"
#include "vtkLKBoneSurfaceFilter.h"
#include "vtkLKMedicalImageReader.h"

#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <cmath>

namespace lktest
{

/// The bone surface of the first TCIA mandible (a fresh copy each call).
inline vtkSmartPointer<vtkPolyData> tciaMandible()
{
  vtkNew<vtkLKMedicalImageReader> reader;
  reader->SetFileName(sampleData("mandible-tcia/test_oncologist_0522c0017_Mandible.nrrd").c_str());
  vtkNew<vtkLKBoneSurfaceFilter> bone;
  bone->SetInputConnection(reader->GetOutputPort());
  bone->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(bone->GetOutput());
  return out;
}

/// A closed feature line around the mandible: the plane x = centre, sampled
/// on the surface and snapped to an edge path. Points carry MeshPointId.
inline vtkSmartPointer<vtkPolyData> mandibleLoop(vtkPolyData* mesh, std::vector<lk::EdgeKey>& edges)
{
  const lk::TriangleMesh tm = lktest::toCore(mesh);
  double b[6];
  mesh->GetBounds(b);
  const double x0 = 0.5 * (b[0] + b[1]);
  // Vertices near the plane, ordered by angle around their centroid in (y, z).
  std::vector<lk::Vec3> near;
  for (const auto& p : tm.points)
    if (std::abs(p.x() - x0) < 0.6)
      near.push_back(p);
  lk::Vec3 c = lk::Vec3::Zero();
  for (const auto& p : near)
    c += p / static_cast<double>(near.size());
  std::sort(near.begin(), near.end(), [&](const lk::Vec3& a, const lk::Vec3& d) {
    return std::atan2(a.z() - c.z(), a.y() - c.y()) < std::atan2(d.z() - c.z(), d.y() - c.y());
  });
  std::vector<lk::Vec3> stroke;
  for (std::size_t i = 0; i < near.size(); i += std::max<std::size_t>(1, near.size() / 24))
    stroke.push_back(near[i]);
  stroke.push_back(stroke.front());
  const auto path = lk::edgePathThrough(tm, stroke);
  auto out = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  vtkNew<vtkIdTypeArray> ids;
  ids->SetName("MeshPointId");
  vtkNew<vtkCellArray> lines;
  lines->InsertNextCell(static_cast<vtkIdType>(path.size()));
  for (std::size_t i = 0; i < path.size(); ++i)
  {
    lines->InsertCellPoint(pts->InsertNextPoint(tm.points[static_cast<std::size_t>(path[i])].data()));
    ids->InsertNextValue(path[i]);
    if (i > 0)
      edges.push_back(lk::edgeKey(path[i - 1], path[i]));
  }
  out->SetPoints(pts);
  out->SetLines(lines);
  out->GetPointData()->AddArray(ids);
  return out;
}


/// A pen stroke near such a loop: every third point, pushed 0.3 mm along x
/// and 0.2 mm along z (the pen is not on the mesh's vertices), closed by its
/// first point again.
inline vtkSmartPointer<vtkPolyData> strokeNearLoop(vtkPolyData* loop)
{
  vtkNew<vtkPoints> pts;
  for (vtkIdType i = 0; i < loop->GetNumberOfPoints(); i += 3)
  {
    double p[3];
    loop->GetPoint(i, p);
    pts->InsertNextPoint(p[0] + 0.3, p[1], p[2] + 0.2);
  }
  double first[3];
  pts->GetPoint(0, first);
  pts->InsertNextPoint(first);
  auto stroke = vtkSmartPointer<vtkPolyData>::New();
  stroke->SetPoints(pts);
  return stroke;
}

} // namespace lktest
