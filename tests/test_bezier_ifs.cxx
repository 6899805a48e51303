#include "latticekit/BezierIFS.h"

#include <gtest/gtest.h>

#include <cmath>
#include <map>

namespace
{
const std::vector<lk::Vec3> kCubic = { { 0, 0, 0 }, { 1, 2, 0 }, { 3, 2, 1 }, { 4, 0, 0 } };

std::vector<lk::Vec3> controlOfDegree(int n)
{
  std::vector<lk::Vec3> c;
  for (int i = 0; i <= n; ++i)
    c.emplace_back(i, std::sin(1.7 * i) * 2.0, std::cos(0.9 * i));
  return c;
}
} // namespace

TEST(BezierIFS, CubicSplitAtOneHalfIsThePapersPair)
{
  const auto maps = lk::bernsteinCurveMaps(3, { 0.5 });
  ASSERT_EQ(maps.size(), 2u);
  Eigen::Matrix4d w1, w2;
  w1 << 0.5, 0, -0.25, -0.375, 0, 0.5, 0.5, 0.375, 0, 0, 0.25, 0.375, 0, 0, 0, 0.125;
  w2 << 0.125, 0, 0, 0, 0.375, 0.25, 0, 0, 0.375, 0.5, 0.5, 0, -0.375, -0.25, 0, 0.5;
  EXPECT_LT((maps[0].A - w1).cwiseAbs().maxCoeff(), 1e-13);
  EXPECT_LT((maps[1].A - w2).cwiseAbs().maxCoeff(), 1e-13);
  EXPECT_LT((maps[0].c - Eigen::Vector4d(0.5, 0, 0, 0)).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_LT((maps[1].c - Eigen::Vector4d(0, 0, 0, 0.5)).cwiseAbs().maxCoeff(), 1e-14);
}

TEST(BezierIFS, MapsAreContractiveForAnySplit)
{
  for (double t : { 0.05, 0.3, 0.5, 0.77, 0.95 })
  {
    for (int n : { 1, 2, 3, 5, 8 })
      for (const auto& w : lk::bernsteinCurveMaps(n, { t }))
      {
        const double rho = lk::spectralRadius(w);
        EXPECT_LT(rho, 1.0) << "degree " << n << " t " << t;
        EXPECT_NEAR(rho, w.s[0], 1e-9); // the largest eigenvalue is the interval's length
      }
    for (const auto& w : lk::bernsteinSurfaceMaps(3, 3, { t }))
      EXPECT_NEAR(lk::spectralRadius(w), std::max({ w.s[0], w.s[1], w.s[0] * w.s[1] }), 1e-9);
    for (const auto& w : lk::quadraticPlanarMaps({ { 0, 0, 0 }, { 1, 2, 0 }, { 2, 0, 0 } }, t))
      EXPECT_LT(lk::spectralRadius(w), 1.0);
  }
}

TEST(BezierIFS, DeterministicAndChaosPointsLieOnTheCurve)
{
  for (int n : { 2, 3, 5 })
  {
    const auto control = controlOfDegree(n);
    // The last two: breaks within rounding of 0 and 1, where 1 - s rounded
    // to 0 and every point was NaN.
    for (const std::vector<double>& breaks : { std::vector<double>{ 0.5 }, std::vector<double>{ 0.3 },
           std::vector<double>{ 0.2, 0.45, 0.8 }, std::vector<double>{ 1e-300 },
           std::vector<double>{ 0.5, 1.0 - 1e-16 } })
    {
      const auto maps = lk::bernsteinCurveMaps(n, breaks);
      const auto det = lk::deterministicIfs(
        maps, { lk::bernsteinCurve(n, 0.0), lk::bernsteinCurve(n, 1.0) }, { { 0, 0 }, { 1, 0 } }, 4, control);
      const auto chaos = lk::chaosGame(maps, std::vector<double>(maps.size(), 1.0 / maps.size()),
        lk::bernsteinCurve(n, 0.0), { 0, 0 }, 20000, 7, control);
      double worst = 0.0;
      for (const auto* set : { &det, &chaos })
        for (std::size_t i = 0; i < set->points.size(); ++i)
        {
          ASSERT_TRUE(set->points[i].allFinite()) << "degree " << n << " break " << breaks[0];
          worst = std::max(worst, (set->points[i] - lk::deCasteljau(control, set->parameters[i][0])).norm());
        }
      EXPECT_LT(worst, 1e-12 * 10.0) << "degree " << n; // the model is about 10 across
      EXPECT_EQ(det.points.size(), 2 * static_cast<std::size_t>(std::pow(maps.size(), 4)));
    }
  }
}

TEST(BezierIFS, BicubicSurfaceFromSixteenDimensions)
{
  std::vector<lk::Vec3> net;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      net.emplace_back(i, j, std::sin(i + 2.0 * j));
  const auto maps = lk::bernsteinSurfaceMaps(3, 3, { 0.5 });
  ASSERT_EQ(maps.size(), 4u);
  ASSERT_EQ(maps[0].A.rows(), 16);
  std::vector<Eigen::VectorXd> base;
  std::vector<std::array<double, 2>> bp = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
  for (const auto& p : bp)
    base.push_back(lk::bernsteinSurface(3, 3, p[0], p[1]));
  const auto det = lk::deterministicIfs(maps, base, bp, 3, net);
  const auto chaos = lk::chaosGame(maps, { 0.25, 0.25, 0.25, 0.25 }, base[0], bp[0], 20000, 11, net);
  double worst = 0.0;
  for (const auto* set : { &det, &chaos })
    for (std::size_t i = 0; i < set->points.size(); ++i)
      worst = std::max(worst,
        (set->points[i] - lk::deCasteljauSurface(net, 3, 3, set->parameters[i][0], set->parameters[i][1])).norm());
  EXPECT_LT(worst, 1e-12 * 5.0);
  EXPECT_EQ(det.points.size(), 4u * 64u);
}

TEST(BezierIFS, ChaosGameDensityIsTheSelfSimilarMeasure)
{
  // p = 1/2 and t = 1/2: uniform in the parameter; chi-square over 32 bins.
  const auto maps = lk::bernsteinCurveMaps(3, { 0.5 });
  const std::size_t N = 200000;
  auto uniform = lk::chaosGame(maps, { 0.5, 0.5 }, lk::bernsteinCurve(3, 0.0), { 0, 0 }, N, 3, kCubic);
  std::vector<double> bins(32, 0.0);
  for (const auto& p : uniform.parameters)
    bins[std::min<std::size_t>(31, static_cast<std::size_t>(p[0] * 32))] += 1.0;
  double chi2 = 0.0;
  for (double b : bins)
    chi2 += (b - N / 32.0) * (b - N / 32.0) / (N / 32.0);
  std::printf("uniform chaos game: chi-square %.1f over 31 degrees of freedom\n", chi2);
  EXPECT_LT(chi2, 61.1); // p = 0.001 critical value for 31 degrees of freedom
  // p = (0.3, 0.7) and t = 0.4: the measure of the depth-3 interval of word
  // (i1, i2, i3) is p_i1 p_i2 p_i3.
  const auto maps2 = lk::bernsteinCurveMaps(3, { 0.4 });
  const double p[2] = { 0.3, 0.7 };
  auto skewed = lk::chaosGame(maps2, { p[0], p[1] }, lk::bernsteinCurve(3, 0.0), { 0, 0 }, N, 5, kCubic);
  std::map<int, double> counts;
  for (const auto& q : skewed.parameters)
  {
    double t = q[0];
    int word = 0;
    for (int d = 0; d < 3; ++d)
    {
      const int i = t < 0.4 ? 0 : 1;
      t = i == 0 ? t / 0.4 : (t - 0.4) / 0.6;
      word = 2 * word + i;
    }
    counts[word] += 1.0;
  }
  chi2 = 0.0;
  for (int word = 0; word < 8; ++word)
  {
    const double expected = N * p[(word >> 2) & 1] * p[(word >> 1) & 1] * p[word & 1];
    chi2 += (counts[word] - expected) * (counts[word] - expected) / expected;
  }
  std::printf("skewed chaos game (p = 0.3, 0.7): chi-square %.1f over 7 degrees of freedom\n", chi2);
  EXPECT_LT(chi2, 24.3); // p = 0.001 critical value for 7 degrees of freedom
}

TEST(BezierIFS, QuadraticPlanarIfsDrawsTheCurve)
{
  const std::vector<lk::Vec3> control = { { 0.1, 0.98, 0 }, { 1.05, 1.7, 0.3 }, { 2.1, 0.2, -0.2 } };
  const auto maps = lk::quadraticPlanarMaps(control, 0.35);
  Eigen::VectorXd start(3);
  start << control[0].x(), control[0].y(), control[0].z();
  const auto chaos = lk::chaosGame(maps, { 0.5, 0.5 }, start, { 0, 0 }, 20000, 9, {});
  double worst = 0.0;
  for (std::size_t i = 0; i < chaos.points.size(); ++i)
    worst = std::max(worst, (chaos.points[i] - lk::deCasteljau(control, chaos.parameters[i][0])).norm());
  EXPECT_LT(worst, 1e-12 * 3.0);
  EXPECT_THROW(lk::quadraticPlanarMaps({ { 0, 0, 0 }, { 1, 1, 1 }, { 2, 2, 2 } }, 0.5), std::invalid_argument);
  EXPECT_THROW(lk::quadraticPlanarMaps(control, 1.0), std::invalid_argument);
  EXPECT_THROW(lk::quadraticPlanarMaps({ control[0], control[1] }, 0.5), std::invalid_argument);
}

TEST(BezierIFS, BadParametersAreRefused)
{
  EXPECT_THROW(lk::bernsteinCurveMaps(3, {}), std::invalid_argument);
  EXPECT_THROW(lk::bernsteinCurveMaps(3, { 0.0 }), std::invalid_argument);
  EXPECT_THROW(lk::bernsteinCurveMaps(3, { 1.2 }), std::invalid_argument);
  EXPECT_THROW(lk::bernsteinCurveMaps(3, { 0.6, 0.4 }), std::invalid_argument);
  EXPECT_THROW(lk::bernsteinCurveMaps(0, { 0.5 }), std::invalid_argument);
  // Too many maps: refused before any is built.
  std::vector<double> many(lk::kMaximumIfsMaps);
  for (std::size_t i = 0; i < many.size(); ++i)
    many[i] = double(i + 1) / double(many.size() + 1);
  EXPECT_THROW(lk::bernsteinCurveMaps(3, many), std::invalid_argument);
  many.pop_back();
  EXPECT_EQ(lk::bernsteinCurveMaps(1, many).size(), lk::kMaximumIfsMaps);
  EXPECT_THROW(lk::bernsteinSurfaceMaps(3, 3, std::vector<double>(many.begin(), many.begin() + 100)),
    std::invalid_argument); // 101 x 101 maps
  const auto maps = lk::bernsteinCurveMaps(3, { 0.5 });
  EXPECT_THROW(lk::chaosGame(maps, { 0.5 }, lk::bernsteinCurve(3, 0), { 0, 0 }, 10, 1, kCubic), std::invalid_argument);
  // A depth whose points pass 50 million says how many and what to lower.
  std::vector<double> breaks(63);
  for (std::size_t i = 0; i < breaks.size(); ++i)
    breaks[i] = double(i + 1) / 64.0;
  const auto sixtyFour = lk::bernsteinCurveMaps(3, breaks);
  const std::vector<Eigen::VectorXd> ends{ lk::bernsteinCurve(3, 0.0), lk::bernsteinCurve(3, 1.0) };
  try
  {
    lk::deterministicIfs(sixtyFour, ends, { { 0, 0 }, { 1, 0 } }, 5, kCubic);
    ADD_FAILURE() << "64 maps to depth 5 (2.1 billion points) were not refused";
  }
  catch (const std::invalid_argument& e)
  {
    EXPECT_STREQ(e.what(), "64 maps to depth 5 give 2.15e+09 points (64^5 x 2), more than 50 million: lower the depth "
                           "or the number of maps");
  }
  EXPECT_THROW(lk::deterministicIfs(maps, ends, { { 0, 0 }, { 1, 0 } }, -1, kCubic), std::invalid_argument);
  EXPECT_EQ(lk::deterministicIfs(sixtyFour, ends, { { 0, 0 }, { 1, 0 } }, 3, kCubic).points.size(), 2u * 64 * 64 * 64);
  EXPECT_THROW(lk::chaosGame(maps, { 0.5, 0.6 }, lk::bernsteinCurve(3, 0), { 0, 0 }, 10, 1, kCubic),
    std::invalid_argument);
}
