#include "latticekit/WrinklyNets.h"
#include "latticekit/WrinklySurface.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <stdexcept>

namespace
{
constexpr int kCells = 9; // 10 x 10 points, 8 x 8 real

lk::WrinklyControlMesh bumpyGrid()
{
  lk::WrinklyControlMesh m = lk::wrinklyRegularNet(kCells, kCells);
  for (std::size_t i = 0; i < m.points.size(); ++i)
    m.points[i].z() = 0.4 * std::sin(1.3 * m.points[i].x()) * std::cos(0.7 * m.points[i].y()) + 0.05 * (i % 3);
  return m;
}

int gridI(int id) { return id % (kCells + 1); }
int gridJ(int id) { return id / (kCells + 1); }

/// Local (u, v) of a point to grid parameters (s along i, r along j).
std::pair<double, double> toGrid(const lk::WrinklyFrame& fr, int id, double u, double v)
{
  double s = 0, r = 0;
  auto place = [&](int role, double t) {
    const int di = gridI(fr.link[role]) - gridI(id), dj = gridJ(fr.link[role]) - gridJ(id);
    if (di != 0)
      s = di > 0 ? t : 1.0 - t;
    else
      r = dj > 0 ? t : 1.0 - t;
  };
  place(lk::PlusU, u);
  place(lk::PlusV, v);
  return { s, r };
}

double quadraticBSpline(int k, double t)
{
  switch (k)
  {
    case 0: return 0.5 * (1 - t) * (1 - t);
    case 1: return 0.5 * (-2 * t * t + 2 * t + 1);
    default: return 0.5 * t * t;
  }
}

std::map<std::pair<int, int>, int> edgeUse(const lk::WrinklyTessellation& t)
{
  std::map<std::pair<int, int>, int> use;
  for (const auto& tri : t.triangles)
    for (int e = 0; e < 3; ++e)
    {
      const int a = tri[e], b = tri[(e + 1) % 3];
      ++use[{ std::min(a, b), std::max(a, b) }];
    }
  return use;
}
} // namespace

TEST(WrinklySurface, RegularBaseIsTheBiquadraticBSpline)
{
  const lk::WrinklyControlMesh m = bumpyGrid();
  lk::WrinklySurface surface(m, {});
  ASSERT_EQ(surface.patchPoints().size(), static_cast<std::size_t>((kCells - 1) * (kCells - 1)));
  double worst = 0.0;
  for (int id : surface.patchPoints())
  {
    const auto& fr = surface.axes().frames[id];
    for (double u : { 0.0, 0.13, 0.5, 0.77, 1.0 })
      for (double v : { 0.0, 0.31, 0.62, 1.0 })
      {
        const auto [s, r] = toGrid(fr, id, u, v);
        lk::Vec3 expected = lk::Vec3::Zero();
        double h = 0.0;
        for (int a = 0; a < 3; ++a)
          for (int b = 0; b < 3; ++b)
          {
            const int q = (gridI(id) + a - 1) + (kCells + 1) * (gridJ(id) + b - 1);
            const double w = quadraticBSpline(a, s) * quadraticBSpline(b, r);
            expected += w * m.points[q];
            h += w * m.heights[q];
          }
        worst = std::max(worst, (surface.basePoint({ id, u, v }) - expected).norm());
        worst = std::max(worst, std::abs(surface.height({ id, u, v }) - h));
      }
  }
  EXPECT_LT(worst, 1e-12);
}

TEST(WrinklySurface, RegularGridGivesTheProductOfTwo1DShuffles)
{
  const lk::WrinklyControlMesh m = bumpyGrid();
  lk::WrinklyParameters p;
  p.shuffleU = 1;
  p.shuffleV = 2;
  p.iterations = 3;
  lk::WrinklySurface surface(m, p);
  const auto& axes = surface.axes();
  int checked = 0;
  for (int id : surface.patchPoints())
    for (double u : { 0.07, 0.41, 0.93 })
      for (double v : { 0.11, 0.52, 0.88 })
      {
        const lk::WrinklyLocal a = surface.inverseShuffle(0, { id, u, v });
        const lk::WrinklyLocal b = surface.inverseShuffle(1, { id, u, v });
        ASSERT_EQ(a.point, b.point);
        EXPECT_NEAR(a.u, b.u, 1e-9);
        EXPECT_NEAR(a.v, b.v, 1e-9);
        // Against the 1D IST along each global axis.
        const auto& fr = axes.frames[id];
        const auto& uAxis = axes.axes[0][fr.axis[0]];
        const lk::IteratedShuffle fu(1, 3);
        const double x = lk::IteratedShuffle::mirrorInto(fu.inverse(fr.index[0] + u), uAxis.points.size());
        const int along = uAxis.points[static_cast<int>(std::floor(x))];
        EXPECT_EQ(axes.frames[a.point].axis[1], axes.frames[along].axis[1]); // same V axis (column or row)
        ++checked;
      }
  EXPECT_GT(checked, 500);
}

TEST(WrinklySurface, ZeroHeightsGiveTheBaseSurfaceExactly)
{
  lk::WrinklyControlMesh m = lk::wrinklyPolygonNet(6, 3, 2);
  std::fill(m.heights.begin(), m.heights.end(), 0.0);
  lk::WrinklySurface surface(m, {});
  for (int id : surface.patchPoints())
    for (double u : { 0.0, 0.3, 1.0 })
      for (double v : { 0.2, 0.9 })
        EXPECT_EQ(surface.surfacePoint({ id, u, v }), surface.basePoint({ id, u, v }));
  const lk::WrinklyTessellation t = lk::tessellateWrinkly(surface, 9);
  for (double h : t.heights)
    EXPECT_EQ(h, 0.0);
}

TEST(WrinklySurface, OneHeightChangesTheSurfaceOnlyInItsSupport)
{
  lk::WrinklyControlMesh m = lk::wrinklyRegularNet(14, 14);
  const int M = 1;
  lk::WrinklyParameters p;
  p.shuffleU = p.shuffleV = M;
  p.iterations = 3;
  const lk::WrinklySurface before(m, p);
  const int qi = 7, qj = 7, q = qi + 15 * qj;
  m.heights[q] += 1.0;
  const lk::WrinklySurface after(m, p);
  int changed = 0, outside = 0;
  for (int id : before.patchPoints())
    for (int a = 0; a < 9; ++a)
      for (int b = 0; b < 9; ++b)
      {
        const lk::WrinklyLocal t{ id, (a + 0.5) / 9, (b + 0.5) / 9 };
        if (std::abs(after.wrinklyHeight(t) - before.wrinklyHeight(t)) > 0.0)
        {
          ++changed;
          // H support: q's patch and its eight neighbours; the IST moves
          // values by at most M base intervals per axis.
          if (std::abs(id % 15 - qi) > M + 1 || std::abs(id / 15 - qj) > M + 1)
            ++outside;
        }
      }
  EXPECT_GT(changed, 0);
  EXPECT_EQ(outside, 0);
}

TEST(WrinklySurface, ParallelAxesCarryTheParameterAcross)
{
  // Eq. 8: the V value at the +u border of a patch, carried to its +u
  // neighbour's V axis, names the same base-surface point.
  const lk::WrinklyControlMesh m = lk::wrinklyPolygonNet(6, 3, 2);
  lk::WrinklySurface surface(m, {});
  const auto& axes = surface.axes();
  int pairs = 0, flips = 0;
  for (int group = 0; group < 2; ++group)
    for (const auto& axis : axes.axes[group])
      for (std::size_t k = 0; k + 1 < axis.points.size(); ++k)
      {
        const int a = axis.points[k], b = axis.points[k + 1];
        const int other = 1 - group;
        for (double local : { 0.2, 0.7 })
        {
          const double value = axes.frames[a].index[other] + local;
          const double carried = lk::parallelParameter(axes, other, a, b, value);
          const double localB = carried - axes.frames[b].index[other];
          const lk::WrinklyLocal ta = group == 0 ? lk::WrinklyLocal{ a, 1.0, local } : lk::WrinklyLocal{ a, local, 1.0 };
          const lk::WrinklyLocal tb = group == 0 ? lk::WrinklyLocal{ b, 0.0, localB } : lk::WrinklyLocal{ b, localB, 0.0 };
          EXPECT_LT((surface.basePoint(ta) - surface.basePoint(tb)).norm(), 1e-12);
          flips += std::abs(localB - local) > 1e-9 ? 1 : 0;
        }
        ++pairs;
      }
  EXPECT_GT(pairs, 50);
  EXPECT_GT(flips, 0); // the net does have axes whose directions disagree
}

TEST(WrinklySurface, IrregularNetsNeedBothOrders)
{
  const lk::WrinklyControlMesh m = lk::wrinklyPolygonNet(6, 3, 2);
  lk::WrinklySurface surface(m, {});
  int differ = 0;
  for (int id : surface.patchPoints())
  {
    const lk::WrinklyLocal a = surface.inverseShuffle(0, { id, 0.37, 0.61 });
    const lk::WrinklyLocal b = surface.inverseShuffle(1, { id, 0.37, 0.61 });
    differ += (a.point != b.point) ? 1 : 0;
  }
  EXPECT_GT(differ, 0);
  // alpha0 = 1 is the U->V order alone.
  lk::WrinklyParameters p;
  p.alpha0 = 1.0;
  p.alpha1 = 0.0;
  lk::WrinklySurface one(m, p);
  for (int id : one.patchPoints())
    EXPECT_DOUBLE_EQ(one.wrinklyHeight({ id, 0.37, 0.61 }), one.height(one.inverseShuffle(0, { id, 0.37, 0.61 })));
}

TEST(WrinklySurface, NetsTessellateWithoutCracks)
{
  for (const auto& net : { lk::wrinklyRegularNet(6, 5), lk::wrinklyPolygonNet(4, 3, 2), lk::wrinklyPolygonNet(6, 3, 2),
         lk::wrinklyPolygonNet(8, 2, 2), lk::wrinklyAnnularNet(12, 4) })
  {
    lk::WrinklySurface surface(net, {});
    const lk::WrinklyTessellation t = lk::tessellateWrinkly(surface, 9);
    const auto use = edgeUse(t);
    for (const auto& [e, n] : use)
      ASSERT_LE(n, 2);
    // A disc: V - E + F = 1, so no cracks and no holes.
    EXPECT_EQ(static_cast<long>(t.points.size()) - static_cast<long>(use.size()) +
        static_cast<long>(t.triangles.size()), 1) << "net with " << net.points.size() << " points";
    ASSERT_EQ(t.attributes.size(), t.points.size() * 3);
  }
}

TEST(WrinklySurface, AnnularCentreHasThreeSidedPatches)
{
  const lk::WrinklyControlMesh m = lk::wrinklyAnnularNet(10, 4);
  lk::WrinklySurface surface(m, {});
  int degenerate = 0;
  for (int id = 0; id < 10; ++id) // the inner ring
  {
    const auto& fr = surface.axes().frames[id];
    ASSERT_TRUE(fr.real);
    int missing = 0;
    for (int r = 0; r < 4; ++r)
      missing += fr.link[r] < 0 ? 1 : 0;
    EXPECT_EQ(missing, 1);
    const auto c = surface.basePatch(id);
    // One side of the 4 x 4 net collapses to a single point.
    for (int side = 0; side < 4; ++side)
    {
      bool collapsed = true;
      for (int k = 1; k < 4; ++k)
      {
        const int i0 = side == 0 ? 0 : side == 1 ? 12 : side == 2 ? 0 : 3;
        const int step = side < 2 ? 1 : 4;
        collapsed = collapsed && (c[i0 + k * step] - c[i0]).norm() < 1e-12;
      }
      degenerate += collapsed ? 1 : 0;
    }
  }
  EXPECT_EQ(degenerate, 10);
  // The rings are cyclic axes, the spokes are not.
  int cyclic = 0;
  for (int g = 0; g < 2; ++g)
    for (const auto& axis : surface.axes().axes[g])
      cyclic += axis.cyclic ? 1 : 0;
  EXPECT_EQ(cyclic, 4); // rings 0 .. 3 (ring 4 is virtual)
}

TEST(WrinklySurface, OneGroupMeshesAreRefused)
{
  for (int sides : { 3, 5 })
  {
    try
    {
      lk::WrinklySurface(lk::wrinklyPolygonNet(sides, 2, 2), {});
      FAIL() << sides << " sides should put every axis in one group";
    }
    catch (const std::invalid_argument& e)
    {
      EXPECT_NE(std::string(e.what()).find("one group"), std::string::npos) << e.what();
    }
  }
}

TEST(WrinklySurface, BadInputIsRefused)
{
  lk::WrinklyControlMesh m = lk::wrinklyRegularNet(4, 4);
  lk::WrinklyParameters p;
  p.alpha0 = 0.7;
  p.alpha1 = 0.7;
  EXPECT_THROW(lk::WrinklySurface(m, p), std::invalid_argument);
  p = {};
  p.shuffleU = -1;
  EXPECT_THROW(lk::WrinklySurface(m, p), std::invalid_argument);
  lk::WrinklyControlMesh border = m;
  border.isVirtual.assign(m.points.size(), 0); // border points cannot be real
  EXPECT_THROW(lk::WrinklySurface(border, {}), std::invalid_argument);
  lk::WrinklyControlMesh nan = m;
  nan.points[7].x() = std::nan("");
  EXPECT_THROW(lk::WrinklySurface(nan, {}), std::invalid_argument);
  lk::WrinklyControlMesh five = lk::wrinklyAnnularNet(5, 3);
  five.faces.erase(five.faces.begin()); // open the centre: inner points are on the border
  five.isVirtual.assign(five.points.size(), 0);
  EXPECT_THROW(lk::WrinklySurface(five, {}), std::invalid_argument);
  lk::WrinklyControlMesh empty;
  EXPECT_THROW(lk::WrinklySurface(empty, {}), std::invalid_argument);
  lk::WrinklySurface ok(m, {});
  EXPECT_THROW(lk::tessellateWrinkly(ok, 0), std::invalid_argument);
  EXPECT_THROW(lk::tessellateWrinkly(ok, 100000), std::invalid_argument);
}

TEST(WrinklySurface, ToleranceChoosesTheLevelOfDetail)
{
  lk::WrinklySurface surface(lk::wrinklyRegularNet(5, 5), {});
  const double size = surface.largestPatchSize();
  EXPECT_EQ(lk::wrinklyIterationsForTolerance(surface, 2 * size), 0);
  EXPECT_EQ(lk::wrinklyIterationsForTolerance(surface, size / 2.9), 1);
  EXPECT_EQ(lk::wrinklyIterationsForTolerance(surface, size / 26.0), 3);
  EXPECT_THROW(lk::wrinklyIterationsForTolerance(surface, -1.0), std::invalid_argument);
}
