#pragma once
/// \file PolygonMesh.h
/// A polygonal mesh (triangles, quads and n-gons mixed): the lattice, the
/// control mesh of a lattice surface.

#include "latticekit/TriangleMesh.h"

#include <string>
#include <vector>

namespace lk
{

struct PolygonMesh
{
  std::vector<Vec3> points;
  std::vector<std::vector<std::int64_t>> faces;
};

/// A triangle mesh as a polygon mesh (a lattice of triangles).
inline PolygonMesh asPolygonMesh(const TriangleMesh& mesh)
{
  PolygonMesh p;
  p.points = mesh.points;
  p.faces.reserve(mesh.triangles.size());
  for (const auto& t : mesh.triangles)
    p.faces.push_back({ t[0], t[1], t[2] });
  return p;
}

/// Newell's vector of face f: its unit normal times twice its area.
inline Vec3 newellVector(const PolygonMesh& mesh, std::size_t f)
{
  const auto& face = mesh.faces[f];
  Vec3 v = Vec3::Zero();
  for (std::size_t i = 0; i < face.size(); ++i)
  {
    v += mesh.points[static_cast<std::size_t>(face[i])].cross(
      mesh.points[static_cast<std::size_t>(face[(i + 1) % face.size()])]);
  }
  return v;
}

/// The checks of latticeProblem that need no topology, in one pass: at least
/// one face, every face with at least three distinct in-range vertices,
/// finite coordinates, no isolated points, non-zero face areas. Empty, or the
/// reason. (The cut adds its own linear-time manifold test to this.)
std::string polygonIndexProblem(const PolygonMesh& mesh);

/// Empty when the mesh is a usable lattice: at least one face, every face with
/// at least three distinct in-range vertices, finite coordinates, no isolated
/// points, non-zero face areas, and a manifold, consistently oriented surface
/// (CGAL's polygon-soup test). Otherwise the reason, as a sentence.
std::string latticeProblem(const PolygonMesh& mesh);

} // namespace lk
