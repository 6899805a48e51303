#include "latticekit/SymmetryPlane.h"

#include "latticekit/ClosestPointTree.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

namespace lk
{

namespace
{

/// FICP's exponent: the trimmed RMS is divided by the kept fraction to this
/// power (the paper's 3; 2 kept fewer points and tilted the plane more on
/// the mandible without a ramus, NOTES session 50).
constexpr double kFractionExponent = 3.0;

/// The mean and largest distance of the mesh's points, mirrored across the
/// plane, to the mesh (each point's distance to the mirror image: a
/// reflection keeps distances), each query hinted by the last hit.
void mirrorDistances(const TriangleMesh& mesh, const ClosestPointTree& tree, SymmetryPlaneResult& result)
{
  const Vec3 n = result.normal, o = result.origin;
  const Eigen::Matrix3d reflection = Eigen::Matrix3d::Identity() - 2.0 * n * n.transpose();
  ClosestPointTree::Hit hint = tree.closest(reflection * (mesh.points[0] - o) + o);
  double sum = 0.0;
  result.maximumDistance = 0.0;
  for (const Vec3& x : mesh.points)
  {
    hint = tree.closest(reflection * (x - o) + o, hint);
    sum += hint.distance;
    result.maximumDistance = std::max(result.maximumDistance, hint.distance);
  }
  result.meanDistance = sum / static_cast<double>(mesh.points.size());
}

}

SymmetryPlaneResult findSymmetryPlane(const TriangleMesh& mesh, const SymmetryPlaneOptions& options)
{
  SymmetryPlaneResult result;
  if (mesh.triangles.empty() || mesh.points.empty())
  {
    result.error = "the surface has no triangles";
    return result;
  }
  if (!(options.trimFraction >= 0.0 && options.trimFraction <= 0.9))
  {
    result.error = "the trim fraction must be 0 to 0.9";
    return result;
  }
  if (!(options.initialNormal.norm() > 0.0) || !options.initialNormal.allFinite())
  {
    result.error = "the initial normal must be a finite, non-zero vector";
    return result;
  }
  Eigen::AlignedBox3d box;
  Vec3 centre = Vec3::Zero();
  for (const Vec3& p : mesh.points)
  {
    if (!p.allFinite())
    {
      result.error = "a point is not finite";
      return result;
    }
    box.extend(p);
    centre += p / static_cast<double>(mesh.points.size());
  }
  const double diagonal = box.diagonal().norm();
  if (!(diagonal > 0.0) || !std::isfinite(diagonal) || !centre.allFinite())
  {
    result.error = diagonal == 0.0 ? "every point is in one place" : "the surface is too large to measure";
    return result;
  }

  const ClosestPointTree tree(mesh);
  const Vec3 n0 = options.initialNormal.normalized();
  // S, the improper motion: first the mirror across the plane through the
  // centre normal to initialNormal.
  Eigen::Affine3d s = Eigen::Affine3d::Identity();
  s.linear() = Eigen::Matrix3d::Identity() - 2.0 * n0 * n0.transpose();
  s.translation() = centre - s.linear() * centre;

  // Where the points' images under S land, the points kept and FICP's
  // measure of it (the lower the better).
  struct Fit
  {
    std::vector<ClosestPointTree::Hit> hits;
    std::vector<std::size_t> order; ///< nearest first; the first `kept` are kept
    std::size_t kept = 0;
    double psi = std::numeric_limits<double>::infinity();
    double rms = 0.0;
  };
  auto evaluate = [&](const std::vector<Vec3>& points, const Eigen::Affine3d& motion, Fit& fit) {
    const std::size_t count = points.size();
    const bool hinted = fit.hits.size() == count;
    fit.hits.resize(count);
    for (std::size_t j = 0; j < count; ++j)
      fit.hits[j] = hinted ? tree.closest(motion * points[j], fit.hits[j]) : tree.closest(motion * points[j]);
    fit.order.resize(count);
    std::iota(fit.order.begin(), fit.order.end(), std::size_t{ 0 });
    std::sort(fit.order.begin(), fit.order.end(), [&](std::size_t a, std::size_t b) {
      return fit.hits[a].distance < fit.hits[b].distance || (fit.hits[a].distance == fit.hits[b].distance && a < b);
    });
    // The fraction kept: the least fractional RMS, from the nearest points.
    const double floor = options.tolerance * diagonal;
    const std::size_t fewest = std::max<std::size_t>(
      3, static_cast<std::size_t>(std::ceil((1.0 - options.trimFraction) * static_cast<double>(count))));
    double sum = 0.0;
    fit.psi = std::numeric_limits<double>::infinity();
    for (std::size_t k = 1; k <= count; ++k)
    {
      const double d = fit.hits[fit.order[k - 1]].distance;
      sum += d * d;
      if (k < fewest && k < count)
        continue;
      const double f = static_cast<double>(k) / static_cast<double>(count);
      const double rms = std::sqrt(sum / static_cast<double>(k));
      // Distances below the tolerance are rounding: on an exactly symmetric
      // surface they would let noise pick the fewest points.
      if (const double psi = std::hypot(rms, floor) / std::pow(f, kFractionExponent); psi < fit.psi)
      {
        fit.psi = psi;
        fit.kept = k;
        fit.rms = rms;
      }
    }
  };
  // The rigid motion that brings the kept points' images closest to the
  // tangent planes at their closest points (point-to-plane ICP, Chen and
  // Medioni 1992; point-to-point slides along a smooth bone for hundreds of
  // iterations), linearised in the rotation: a 6x6 least-squares solve. A
  // little damping keeps a motion the surface does not fix (a turn of a
  // sphere about its centre) at zero.
  auto step = [&](const std::vector<Vec3>& points, const Eigen::Affine3d& motion, const Fit& fit) {
    Eigen::Matrix<double, 6, 6> normalMatrix = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> rightSide = Eigen::Matrix<double, 6, 1>::Zero();
    for (std::size_t k = 0; k < fit.kept; ++k)
    {
      const ClosestPointTree::Hit& hit = fit.hits[fit.order[k]];
      const Triangle& t = mesh.triangles[static_cast<std::size_t>(hit.face)];
      const Vec3& a = mesh.points[static_cast<std::size_t>(t[0])];
      const Vec3 faceNormal = (mesh.points[static_cast<std::size_t>(t[1])] - a)
                                .cross(mesh.points[static_cast<std::size_t>(t[2])] - a)
                                .normalized();
      if (!faceNormal.allFinite())
        continue; // a degenerate triangle has no tangent plane
      const Vec3 y = motion * points[fit.order[k]];
      Eigen::Matrix<double, 6, 1> row;
      row << y.cross(faceNormal), faceNormal;
      normalMatrix += row * row.transpose();
      rightSide -= row * faceNormal.dot(y - hit.point);
    }
    normalMatrix.diagonal().array() += 1e-9 * normalMatrix.trace() + std::numeric_limits<double>::min();
    const Eigen::Matrix<double, 6, 1> solution = normalMatrix.ldlt().solve(rightSide);
    Eigen::Affine3d rigid = Eigen::Affine3d::Identity();
    const Vec3 turn = solution.head<3>();
    if (turn.norm() > 0.0)
      rigid.linear() = Eigen::AngleAxisd(turn.norm(), turn.normalized()).toRotationMatrix();
    rigid.translation() = solution.tail<3>();
    return rigid;
  };

  // The points registered, evenly spread; a tenth of them first, to come
  // near at a tenth of the cost, then all.
  const std::size_t stride =
    std::max<std::size_t>(1, mesh.points.size() / std::max<std::size_t>(1, options.maximumPoints));
  std::vector<Vec3> working, coarse;
  for (std::size_t i = 0; i < mesh.points.size(); i += stride)
    working.push_back(mesh.points[i]);
  for (std::size_t i = 0; i < working.size(); i += 10)
    coarse.push_back(working[i]);
  const bool twoStages = coarse.size() >= 1000;
  Fit fit;
  for (const std::vector<Vec3>* points : { &coarse, &working })
  {
    if (points == &coarse && !twoStages)
      continue;
    // ICP stops when no point moves farther than the tolerance, or when its
    // measure has not improved for a while (on a skull the closest points
    // can hop between the inner and outer tables, and the motion wanders by
    // a tenth of a millimetre); the best motion seen is kept.
    fit = Fit();
    Eigen::Affine3d best = s;
    double bestPsi = std::numeric_limits<double>::infinity();
    int sinceBetter = 0;
    const double share = twoStages ? (points == &coarse ? 0.5 : 1.0) : 1.0;
    const double before = twoStages && points == &working ? 0.5 : 0.0;
    for (int iteration = 0; iteration < options.maximumIterations; ++iteration)
    {
      evaluate(*points, s, fit);
      if (fit.psi < bestPsi * (1.0 - 1e-6))
      {
        bestPsi = fit.psi;
        best = s;
        sinceBetter = 0;
      }
      else if (++sinceBetter >= 10)
        break;
      const Eigen::Affine3d rigid = step(*points, s, fit);
      if (!rigid.matrix().allFinite())
      {
        result.error = "the registration diverged";
        return result;
      }
      double moved = 0.0;
      for (const Vec3& x : *points)
      {
        const Vec3 y = s * x;
        moved = std::max(moved, (rigid * y - y).norm());
      }
      s = rigid * s;
      ++result.iterations;
      if (options.progress &&
        !options.progress(before + share * static_cast<double>(iteration + 1) / options.maximumIterations))
      {
        result.stopped = true;
        return result;
      }
      if (moved < options.tolerance * diagonal)
        break;
    }
    // The last motion unless an earlier one was better.
    evaluate(*points, s, fit);
    if (fit.psi > bestPsi)
    {
      s = best;
      evaluate(*points, s, fit);
    }
  }
  result.keptFraction = static_cast<double>(fit.kept) / static_cast<double>(working.size());
  result.keptRMS = fit.rms;
  const std::size_t kept = fit.kept;
  const std::vector<std::size_t>& order = fit.order;

  // The reflection nearest S: its symmetric part's eigenvector of the least
  // eigenvalue (-1 for a reflection) is the normal.
  const Eigen::Matrix3d symmetric = 0.5 * (s.linear() + s.linear().transpose());
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(symmetric);
  Vec3 n = eigen.eigenvectors().col(0).normalized();
  if (n.dot(n0) < 0.0)
    n = -n;
  // Through the midpoints of the points kept and their images.
  double offset = 0.0;
  for (std::size_t k = 0; k < kept; ++k)
  {
    const Vec3& x = working[order[k]];
    offset += n.dot(0.5 * (x + s * x)) / static_cast<double>(kept);
  }
  result.normal = n;
  result.origin = centre - (n.dot(centre) - offset) * n;
  if (!result.normal.allFinite() || !result.origin.allFinite())
  {
    result.error = "the registration gave no finite plane";
    return result;
  }
  mirrorDistances(mesh, tree, result);
  result.ok = true;
  return result;
}

SymmetryPlaneResult measureMirror(const TriangleMesh& mesh, const Vec3& origin, const Vec3& normal)
{
  SymmetryPlaneResult result;
  result.keptFraction = 0.0;
  if (mesh.triangles.empty() || mesh.points.empty())
    result.error = "the surface has no triangles";
  else if (!origin.allFinite() || !normal.allFinite() || !(normal.norm() > 0.0))
    result.error = "the plane must have a finite point and a finite, non-zero normal";
  else if (std::any_of(mesh.points.begin(), mesh.points.end(), [](const Vec3& p) { return !p.allFinite(); }))
    result.error = "a point is not finite";
  if (!result.error.empty())
    return result;
  result.origin = origin;
  result.normal = normal.normalized();
  const ClosestPointTree tree(mesh);
  mirrorDistances(mesh, tree, result);
  result.ok = true;
  return result;
}

} // namespace lk
