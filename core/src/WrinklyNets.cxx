#include "latticekit/WrinklyNets.h"

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>

namespace lk
{
namespace
{

/// Heights in [-a, a] and colours in [0, 1] from a small linear congruential
/// generator: the same numbers on every machine.
void decorate(WrinklyControlMesh& m, const WrinklyNetStyle& style)
{
  unsigned state = style.seed * 2654435761u + 12345u;
  auto next = [&]() {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>(state >> 8) / static_cast<double>(1u << 24);
  };
  m.heights.resize(m.points.size());
  m.attributeComponents = 3;
  m.attributes.resize(m.points.size() * 3);
  for (std::size_t i = 0; i < m.points.size(); ++i)
  {
    m.heights[i] = style.heightAmplitude * (2.0 * next() - 1.0);
    for (int c = 0; c < 3; ++c)
      m.attributes[i * 3 + c] = next();
  }
}

void requireAtLeast(int value, int least, const char* what)
{
  if (value < least)
    throw std::invalid_argument(std::string(what) + " must be at least " + std::to_string(least));
}

} // namespace

WrinklyControlMesh wrinklyRegularNet(int cellsU, int cellsV, const WrinklyNetStyle& style)
{
  requireAtLeast(cellsU, 2, "cellsU");
  requireAtLeast(cellsV, 2, "cellsV");
  WrinklyControlMesh m;
  for (int j = 0; j <= cellsV; ++j)
    for (int i = 0; i <= cellsU; ++i)
      m.points.emplace_back(i * style.spacing, j * style.spacing, 0.0);
  auto id = [&](int i, int j) { return i + (cellsU + 1) * j; };
  for (int j = 0; j < cellsV; ++j)
    for (int i = 0; i < cellsU; ++i)
      m.faces.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1) });
  decorate(m, style);
  return m;
}

WrinklyControlMesh wrinklyPolygonNet(int sides, int rings, int edgeCells, const WrinklyNetStyle& style)
{
  requireAtLeast(sides, 3, "sides");
  requireAtLeast(rings, 1, "rings");
  requireAtLeast(edgeCells, 1, "edgeCells");
  const double d = style.spacing;
  const double radius = edgeCells * d / (2.0 * std::sin(M_PI / sides));
  std::vector<Vec3> corner(sides), normal(sides);
  for (int j = 0; j < sides; ++j)
  {
    const double a = 2.0 * M_PI * j / sides;
    corner[j] = Vec3(radius * std::cos(a), radius * std::sin(a), 0.0);
    const double b = 2.0 * M_PI * (j + 0.5) / sides;
    normal[j] = Vec3(std::cos(b), std::sin(b), 0.0); // outward normal of side j (corner j to j + 1)
  }
  WrinklyControlMesh m;
  // Wedge j at corner j: W(a, b) = corner_j + a d n_(j-1) + b d n_j. Side i's
  // strip S(s, r) = corner_i + s/E (corner_(i+1) - corner_i) + r d n_i, with
  // S(0, r) = W_i(0, r) and S(E, r) = W_(i+1)(r, 0).
  std::map<std::tuple<int, int, int, int>, int> index;
  auto wedge = [&](int j, int a, int b) {
    j = (j % sides + sides) % sides;
    const auto key = std::make_tuple(0, j, a, b);
    auto it = index.find(key);
    if (it != index.end())
      return it->second;
    const int id = static_cast<int>(m.points.size());
    m.points.push_back(corner[j] + a * d * normal[(j + sides - 1) % sides] + b * d * normal[j]);
    index.emplace(key, id);
    return id;
  };
  auto strip = [&](int i, int s, int r) {
    if (s == 0)
      return wedge(i, 0, r);
    if (s == edgeCells)
      return wedge(i + 1, r, 0);
    const auto key = std::make_tuple(1, i, s, r);
    auto it = index.find(key);
    if (it != index.end())
      return it->second;
    const int id = static_cast<int>(m.points.size());
    m.points.push_back(corner[i] + (static_cast<double>(s) / edgeCells) * (corner[(i + 1) % sides] - corner[i]) +
      r * d * normal[i]);
    index.emplace(key, id);
    return id;
  };
  std::vector<int> centre; // every point on the central cell's border, or it would have T-junctions
  for (int i = 0; i < sides; ++i)
    for (int s = 0; s < edgeCells; ++s)
      centre.push_back(strip(i, s, 0));
  m.faces.push_back(centre);
  for (int i = 0; i < sides; ++i)
  {
    for (int s = 0; s < edgeCells; ++s)
      for (int r = 0; r < rings; ++r)
        m.faces.push_back({ strip(i, s, r), strip(i, s, r + 1), strip(i, s + 1, r + 1), strip(i, s + 1, r) });
    for (int a = 0; a < rings; ++a)
      for (int b = 0; b < rings; ++b)
        m.faces.push_back({ wedge(i, a, b), wedge(i, a + 1, b), wedge(i, a + 1, b + 1), wedge(i, a, b + 1) });
  }
  decorate(m, style);
  return m;
}

WrinklyControlMesh wrinklyAnnularNet(int spokes, int rings, const WrinklyNetStyle& style)
{
  requireAtLeast(spokes, 3, "spokes");
  requireAtLeast(rings, 2, "rings");
  const double d = style.spacing;
  const double r0 = spokes * d / (2.0 * M_PI);
  WrinklyControlMesh m;
  for (int k = 0; k <= rings; ++k)
    for (int s = 0; s < spokes; ++s)
    {
      const double a = 2.0 * M_PI * s / spokes;
      m.points.emplace_back((r0 + k * d) * std::cos(a), (r0 + k * d) * std::sin(a), 0.0);
    }
  auto id = [&](int k, int s) { return k * spokes + (s % spokes); };
  std::vector<int> centre;
  for (int s = 0; s < spokes; ++s)
    centre.push_back(id(0, s));
  m.faces.push_back(centre);
  for (int k = 0; k < rings; ++k)
    for (int s = 0; s < spokes; ++s)
      m.faces.push_back({ id(k, s), id(k + 1, s), id(k + 1, s + 1), id(k, s + 1) });
  decorate(m, style);
  return m;
}

} // namespace lk
