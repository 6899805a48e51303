#pragma once
/// \file QuadPairing.h
/// Pairing of triangles into quads where precision is not needed (seed 004,
/// sections 3.3.2 and 3.3.3). A quad of the lattice takes one Gregory patch
/// where a triangle takes three, so pairing cuts the display polygons.
///
/// Two triangles (u, v, x) and (v, u, y) across their shared edge (u, v), the
/// diagonal, become the quad (u, y, v, x) when:
/// - eq. 3.15 (printed as 3.16 in the text): the two angles facing the
///   diagonal, at x and at y, are near right: |cos(angle x)| + |cos(angle y)| < S1;
/// - eq. 3.16 (printed 3.17): the quad's angles at the diagonal's two ends
///   (each the sum of the two triangle angles there) differ by less than S2
///   radians, which refuses the kite of fig. 3.10 whose facing angles are
///   right but whose ends are sharp. (The printed form compares sums of
///   cosines; comparing the angles themselves is what the text describes.);
/// - the dihedral angle between the two triangles is at most maxDihedralDegrees;
/// - the diagonal is not a feature edge (feature edges never disappear).
/// Candidates are taken greedily from a heap in order of the diagonal's cost
/// (the QEM cost of the edge from the simplification when given; otherwise
/// (1 - cos dihedral) times the squared diagonal length, which is zero for a
/// planar pair); each triangle pairs at most once.

#include "latticekit/LatticeSimplification.h"
#include "latticekit/PolygonMesh.h"

#include <map>
#include <set>
#include <vector>

namespace lk
{

struct QuadPairingOptions
{
  double rightAngleTolerance = 0.5;  ///< S1 of eq. 3.15, > 0
  double angleSumTolerance = 0.5;    ///< S2 of eq. 3.16, radians, > 0
  double maxDihedralDegrees = 30.0;  ///< in [0, 180]
};

struct QuadPairingResult
{
  PolygonMesh lattice;          ///< quads and the triangles left unpaired
  /// Every output face: the input triangles it came from (one or two).
  std::vector<std::vector<std::int64_t>> faceTriangles;
  std::size_t quads = 0;
};

/// Pairs the triangles of a manifold triangle lattice. `costs` (optional) gives
/// the diagonal cost per edge; edges missing from it get the geometric cost.
/// Throws std::invalid_argument for tolerances out of range or a mesh that is
/// not a manifold triangle mesh.
QuadPairingResult pairTrianglesIntoQuads(const TriangleMesh& mesh, const std::set<EdgeKey>& featureEdges,
  const QuadPairingOptions& options, const std::map<EdgeKey, double>* costs = nullptr);

} // namespace lk
