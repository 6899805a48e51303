#include "latticekit/QuadPairing.h"

#include "latticekit/ManifoldRepair.h"

#include <cmath>
#include <queue>
#include <stdexcept>
#include <tuple>

namespace lk
{
namespace
{
struct Candidate
{
  double cost;
  std::int64_t t1, t2; ///< t1 holds u -> v, t2 holds v -> u
  std::int64_t u, v, x, y;
  bool operator>(const Candidate& o) const
  {
    return std::tie(cost, t1, t2) > std::tie(o.cost, o.t1, o.t2);
  }
};
} // namespace

QuadPairingResult pairTrianglesIntoQuads(const TriangleMesh& mesh, const std::set<EdgeKey>& featureEdges,
  const QuadPairingOptions& options, const std::map<EdgeKey, double>* costs)
{
  if (!(options.rightAngleTolerance > 0.0) || !std::isfinite(options.rightAngleTolerance))
    throw std::invalid_argument("the right-angle tolerance S1 must be a finite number above 0");
  if (!(options.angleSumTolerance > 0.0) || !std::isfinite(options.angleSumTolerance))
    throw std::invalid_argument("the angle-sum tolerance S2 must be a finite number above 0");
  if (!(options.maxDihedralDegrees >= 0.0 && options.maxDihedralDegrees <= 180.0))
    throw std::invalid_argument("the largest dihedral angle must lie in [0, 180] degrees");
  const std::string problem = cgalSurfaceMeshProblem(mesh);
  if (!problem.empty())
    throw std::invalid_argument(problem);

  // Directed edge -> triangle.
  std::map<std::pair<std::int64_t, std::int64_t>, std::int64_t> owner;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int i = 0; i < 3; ++i)
      owner[{ mesh.triangles[t][static_cast<std::size_t>(i)], mesh.triangles[t][static_cast<std::size_t>((i + 1) % 3)] }] =
        static_cast<std::int64_t>(t);
  auto third = [&](std::int64_t t, std::int64_t a, std::int64_t b) {
    for (auto v : mesh.triangles[static_cast<std::size_t>(t)])
      if (v != a && v != b)
        return v;
    return std::int64_t(-1);
  };
  auto P = [&](std::int64_t i) -> const Vec3& { return mesh.points[static_cast<std::size_t>(i)]; };

  const double cosDihedral = std::cos(options.maxDihedralDegrees * kPi / 180.0);
  std::priority_queue<Candidate, std::vector<Candidate>, std::greater<Candidate>> heap;
  for (const auto& [directed, t1] : owner)
  {
    const auto [u, v] = directed;
    if (u > v)
      continue; // each edge once, from its u < v side
    const auto back = owner.find({ v, u });
    if (back == owner.end())
      continue; // boundary edge
    if (featureEdges.count(edgeKey(u, v)))
      continue;
    const std::int64_t t2 = back->second;
    const std::int64_t x = third(t1, u, v), y = third(t2, u, v);
    const Vec3 n1 = (P(v) - P(u)).cross(P(x) - P(u)), n2 = (P(u) - P(v)).cross(P(y) - P(v));
    const double len = n1.norm() * n2.norm();
    if (!(len > 0.0) || n1.dot(n2) < cosDihedral * len)
      continue;
    // Eq. 3.15: the angles facing the diagonal near right.
    if (std::abs(std::cos(angleAt(P(x), P(u), P(v)))) + std::abs(std::cos(angleAt(P(y), P(u), P(v)))) >=
      options.rightAngleTolerance)
      continue;
    // Eq. 3.16: balanced angles at the diagonal's ends.
    const double atU = angleAt(P(u), P(v), P(x)) + angleAt(P(u), P(y), P(v));
    const double atV = angleAt(P(v), P(x), P(u)) + angleAt(P(v), P(u), P(y));
    if (std::abs(atU - atV) >= options.angleSumTolerance)
      continue;
    double cost = (1.0 - n1.dot(n2) / len) * (P(v) - P(u)).squaredNorm();
    if (costs)
    {
      const auto it = costs->find(edgeKey(u, v));
      if (it != costs->end())
        cost = it->second;
    }
    heap.push({ cost, t1, t2, u, v, x, y });
  }

  QuadPairingResult result;
  result.lattice.points = mesh.points;
  std::vector<char> paired(mesh.triangles.size(), 0);
  while (!heap.empty())
  {
    const Candidate c = heap.top();
    heap.pop();
    if (paired[static_cast<std::size_t>(c.t1)] || paired[static_cast<std::size_t>(c.t2)])
      continue;
    paired[static_cast<std::size_t>(c.t1)] = paired[static_cast<std::size_t>(c.t2)] = 1;
    result.lattice.faces.push_back({ c.u, c.y, c.v, c.x });
    result.faceTriangles.push_back({ c.t1, c.t2 });
    ++result.quads;
  }
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
  {
    if (paired[t])
      continue;
    const Triangle& tri = mesh.triangles[t];
    result.lattice.faces.push_back({ tri[0], tri[1], tri[2] });
    result.faceTriangles.push_back({ static_cast<std::int64_t>(t) });
  }
  return result;
}

} // namespace lk
