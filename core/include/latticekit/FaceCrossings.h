#pragma once
/// \file FaceCrossings.h
/// Where a surface passes through itself near some of its faces: the pairs
/// of faces that cross, at least one of them marked. The cut asks it of its
/// caps (a cap that crosses the bone or another cap); the planner asks it of
/// the faces a deformation moved (a bump or box pushed through the bone's
/// other side). Either way the piece is then no valid solid to print.

#include "latticekit/PolygonMesh.h"

#include <cstddef>
#include <vector>

namespace lk
{

struct FaceCrossings
{
  std::size_t pairs = 0; ///< pairs of faces that cross, at least one marked
  double depth = 0.0;    ///< the deepest pair's overlap (mesh units)
  bool checked = true;   ///< false: not even the whole mesh is a surface CGAL can hold
};

/// The pairs of faces of `mesh` that cross each other, at least one of them
/// marked (`marked[f]` non-zero; one entry per face). Only the marked faces'
/// neighbourhood can hold such a pair, so CGAL's self-intersection test runs
/// on the faces whose boxes meet the marked faces' box, fanned into
/// triangles; on the whole mesh where that subset is not a manifold surface
/// CGAL can hold. Pairs that only touch (reaching through each other by less
/// than 1e-6 of the mesh's size) are not counted. `depth` is the deepest
/// pair's overlap: how far each triangle reaches through the other's plane
/// on its shallower side, the smaller of the two. Nothing marked: no pairs.
/// The mesh must have valid face indices (polygonIndexProblem).
FaceCrossings markedFaceCrossings(const PolygonMesh& mesh, const std::vector<char>& marked);

/// markedFaceCrossings with every face whose box meets the box [low, high]
/// marked: the crossings a region of the mesh holds (the deformation filter
/// asks it of its input around the faces it moved).
FaceCrossings crossingsInBox(const PolygonMesh& mesh, const Vec3& low, const Vec3& high);

} // namespace lk
