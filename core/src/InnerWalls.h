#pragma once
/// \file InnerWalls.h
/// Private to the cut (MeshCut.cxx): on a hollow bone, a line drawn around
/// the outside does not reach the inner wall (a marrow cavity, a canal) that
/// its saw cut would pass through. This finds those walls' sections by the
/// line's plane and splits the mesh along them, so that the cut can follow.

#include "latticekit/PolygonMesh.h"

#include <cstdint>
#include <vector>

namespace lk
{
namespace cut
{

/// A mesh split along the inner walls that a loop goes around, and those
/// walls' new loops.
struct InnerWalls
{
  PolygonMesh mesh;                      ///< the input's points first, then the new ones
  std::vector<std::int64_t> faceParent;  ///< the input face of each face
  std::vector<std::vector<std::int64_t>> loops;
};

/// The sections of the mesh by a flat loop's plane that lie inside the loop
/// (projected onto the plane) and away from it: on a hollow bone, the inner
/// wall (the marrow cavity or a canal) that a line drawn around the outside
/// does not reach. Each becomes a loop of new vertices where triangle edges
/// cross the plane; the triangles it crosses are split. Where a vertex lies
/// on the plane the plane is moved by a hair, so that no new vertex falls on
/// an old one. Sections through faces that are not triangles are left out.
/// `onLoop`: per mesh vertex, whether it is on a loop (sections that come
/// near one are not kept).
InnerWalls splitAlongInnerWalls(const PolygonMesh& mesh, const std::vector<std::int64_t>& loop,
  const std::vector<char>& onLoop);

} // namespace cut
} // namespace lk
