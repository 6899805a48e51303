#pragma once
/// \file SymmetryPlane.h
/// A surface's plane of symmetry by trimmed, reflective ICP: the surface's
/// points, mirrored, are registered rigidly onto the surface itself, and the
/// plane is the reflection nearest the improper motion found. At every
/// iteration the points whose mirror lands farthest from the surface are
/// left out, in the fraction that the fractional RMS criterion of FICP
/// (Phillips, Liu and Tomasi 2007: the trimmed RMS divided by the cube of
/// the kept fraction) picks, up to `trimFraction`: a one-sided tumour or a
/// missing ramus (and the healthy part mirrored onto the gap) do not pull
/// the plane, and a symmetric bone keeps nearly all its points.

#include "latticekit/TriangleMesh.h"

#include <functional>
#include <string>

namespace lk
{

struct SymmetryPlaneOptions
{
  /// Roughly the plane's normal (the patient's left-right axis); the first
  /// mirror is across the plane through the points' centre normal to it.
  Vec3 initialNormal{ 1.0, 0.0, 0.0 };
  /// The largest fraction of points an iteration may leave out, 0 (plain
  /// ICP) to 0.9.
  double trimFraction = 0.5;
  /// Iterations of each stage. They stop sooner when no point moved farther
  /// than `tolerance` times the bounding box's diagonal, or when the trimmed
  /// fit has not improved for 10 iterations (the best motion is kept).
  int maximumIterations = 200;
  double tolerance = 1e-6;
  /// The points registered: all up to this many, else as many evenly spread
  /// (by index, which for a marching-cubes surface is spread over the bone).
  /// Where that is 10,000 or more, a tenth of them is registered first, to
  /// come near at a tenth of the cost.
  std::size_t maximumPoints = 20000;
  /// Called with the fraction done (iterations / maximumIterations);
  /// returning false stops, with `stopped` set.
  std::function<bool(double)> progress;
};

struct SymmetryPlaneResult
{
  Vec3 origin{ Vec3::Zero() };
  Vec3 normal{ Vec3::UnitX() }; ///< unit, on initialNormal's side
  double keptFraction = 1.0;    ///< of the points, at the last iteration
  double keptRMS = 0.0;         ///< their RMS distance to the surface, mirrored
  /// How far the surface is from its mirror image across the plane: the
  /// mean and largest distance of every point of the mesh, mirrored, to the
  /// surface (a point's distance to the mirror image, since a reflection
  /// keeps distances).
  double meanDistance = 0.0;
  double maximumDistance = 0.0;
  int iterations = 0;
  bool stopped = false;
  bool ok = false;
  std::string error; ///< why not ok
};

/// The plane of symmetry of `mesh` (at least one triangle; finite points).
SymmetryPlaneResult findSymmetryPlane(const TriangleMesh& mesh, const SymmetryPlaneOptions& options = {});

/// How far `mesh` is from its mirror image across the plane through `origin`
/// with unit `normal` (a plane set by hand): meanDistance and
/// maximumDistance over every point, as findSymmetryPlane reports them;
/// keptFraction 0 (nothing was fitted). Not ok, with the error, for a mesh
/// without triangles, a point or a plane that is not finite, a zero normal.
SymmetryPlaneResult measureMirror(const TriangleMesh& mesh, const Vec3& origin, const Vec3& normal);

} // namespace lk
