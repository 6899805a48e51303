#include "latticekit/IteratedShuffle.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <stdexcept>
#include <vector>

namespace
{
/// Every level-K label of base intervals [lo, hi).
std::vector<lk::ShuffleLabel> allLabels(const lk::IteratedShuffle& f, int lo, int hi)
{
  std::vector<lk::ShuffleLabel> out;
  for (int b = lo; b < hi; ++b)
    for (std::int64_t q = 0; q < f.piecesPerBase(); ++q)
    {
      lk::ShuffleLabel l;
      l.base = b;
      l.digits.resize(f.iterations());
      std::int64_t r = q;
      for (int k = f.iterations() - 1; k >= 0; --k)
      {
        l.digits[k] = static_cast<int>(r % f.pieces());
        r /= f.pieces();
      }
      out.push_back(l);
    }
  return out;
}

std::vector<int> key(const lk::ShuffleLabel& l)
{
  std::vector<int> k{ static_cast<int>(l.base) };
  k.insert(k.end(), l.digits.begin(), l.digits.end());
  return k;
}
} // namespace

TEST(IteratedShuffle, FigureOneNumbering)
{
  // M = 1, one iteration: base interval 6 of the target axis holds pieces
  // 50, 61, 72 (neighbours interleaved); after two iterations its first
  // third is 5 digits ... as the closed form says, and 6 -> 60, 61, 62.
  lk::IteratedShuffle f(1, 1);
  std::vector<std::vector<int>> got;
  for (int e = 0; e < 3; ++e)
    got.push_back(key(f.inverse(lk::ShuffleLabel{ 6, { e } })));
  EXPECT_EQ(got, (std::vector<std::vector<int>>{ { 5, 0 }, { 6, 1 }, { 7, 2 } }));
}

TEST(IteratedShuffle, BijectionForEveryIterationCount)
{
  for (int M : { 0, 1, 2 })
    for (int K = 0; K <= 4; ++K)
    {
      // Cyclic axis: a permutation of all labels.
      lk::IteratedShuffle cyc(M, K, lk::ShuffleAxis::Cyclic, 5);
      const auto labels = allLabels(cyc, 0, 5);
      std::set<std::vector<int>> targets;
      for (const auto& s : labels)
      {
        const auto t = cyc.forward(s);
        EXPECT_GE(t.base, 0);
        EXPECT_LT(t.base, 5);
        targets.insert(key(t));
        EXPECT_EQ(key(cyc.inverse(t)), key(s));
      }
      EXPECT_EQ(targets.size(), labels.size()) << "M " << M << " K " << K;
      // Translation axis: injective, and onto the middle of a window.
      lk::IteratedShuffle tr(M, K);
      std::set<std::vector<int>> images;
      for (const auto& s : allLabels(tr, -10, 10))
      {
        images.insert(key(tr.forward(s)));
        EXPECT_EQ(key(tr.inverse(tr.forward(s))), key(s));
      }
      EXPECT_EQ(images.size(), allLabels(tr, -10, 10).size());
      for (const auto& t : allLabels(tr, -10 + M, 10 - M))
        EXPECT_TRUE(images.count(key(t)));
    }
}

TEST(IteratedShuffle, ContinuousMapIsPiecewiseTranslation)
{
  lk::IteratedShuffle f(1, 3);
  for (int i = 0; i < 2000; ++i)
  {
    const double x = -3.0 + 6.0 * ((i * 7919) % 2000 + 0.5) / 2000.0;
    const double y = f.forward(x);
    EXPECT_NEAR(f.inverse(y), x, 1e-12);
    // Inside x's piece the map is a translation.
    const lk::ShuffleLabel l = f.labelOf(x);
    const double start = f.startOf(l), width = 1.0 / f.piecesPerBase();
    const double x2 = start + 0.25 * width, x3 = start + 0.75 * width;
    EXPECT_NEAR(f.forward(x3) - f.forward(x2), x3 - x2, 1e-12);
  }
}

TEST(IteratedShuffle, PiecesMoveAtMostMBaseIntervals)
{
  for (int M : { 1, 2, 3 })
    for (int K : { 1, 2, 5 })
    {
      lk::IteratedShuffle f(M, K);
      if (f.piecesPerBase() > 20000)
        continue;
      std::int64_t largest = 0;
      for (const auto& s : allLabels(f, 0, 1))
      {
        const auto t = f.forward(s);
        largest = std::max<std::int64_t>(largest, std::llabs(t.base - s.base));
      }
      EXPECT_EQ(largest, M) << "M " << M << " K " << K; // bounded by M, and reached
    }
}

TEST(IteratedShuffle, LocalResemblanceAtEveryIterationCount)
{
  // In every window (a target sub-interval at level k < K), the leading
  // digits (source base intervals, as offsets 0 .. 2M) under child c + 1 are
  // those under child c shifted by one, mod 2M + 1.
  for (int M : { 1, 2 })
    for (int K = 1; K <= 4; ++K)
    {
      lk::IteratedShuffle f(M, K);
      const int n = f.pieces();
      for (int t = -2; t <= 2; ++t)
      {
        std::vector<int> lead; // per level-K slot of base interval t
        for (const auto& l : allLabels(f, t, t + 1))
          lead.push_back(static_cast<int>(f.inverse(l).base - t + M));
        for (int k = 0; k < K; ++k)
        {
          std::int64_t window = 1; // slots per window at level k
          for (int j = k; j < K; ++j)
            window *= n;
          const std::int64_t child = window / n;
          for (std::int64_t w0 = 0; w0 < static_cast<std::int64_t>(lead.size()); w0 += window)
            for (int c = 0; c + 1 < n; ++c)
              for (std::int64_t s = 0; s < child; ++s)
                ASSERT_EQ(lead[w0 + (c + 1) * child + s], (lead[w0 + c * child + s] + 1) % n)
                  << "M " << M << " K " << K << " level " << k;
        }
        // And the pattern is not trivial: every offset occurs.
        EXPECT_EQ(std::set<int>(lead.begin(), lead.end()).size(), static_cast<std::size_t>(n));
      }
    }
}

TEST(IteratedShuffle, ZeroIterationsIsTheIdentity)
{
  lk::IteratedShuffle f(2, 0);
  for (double x : { -1.7, 0.0, 0.3, 4.99 })
  {
    EXPECT_DOUBLE_EQ(f.forward(x), x);
    EXPECT_DOUBLE_EQ(f.inverse(x), x);
  }
}

TEST(IteratedShuffle, MirrorKeepsInsideTheAxis)
{
  EXPECT_DOUBLE_EQ(lk::IteratedShuffle::mirrorInto(-0.25, 4.0), 0.25);
  EXPECT_DOUBLE_EQ(lk::IteratedShuffle::mirrorInto(4.5, 4.0), 3.5);
  EXPECT_DOUBLE_EQ(lk::IteratedShuffle::mirrorInto(2.0, 4.0), 2.0);
  EXPECT_LT(lk::IteratedShuffle::mirrorInto(4.0, 4.0), 4.0);
}

TEST(IteratedShuffle, BadParametersAreRefused)
{
  EXPECT_THROW(lk::IteratedShuffle(-1, 2), std::invalid_argument);
  EXPECT_THROW(lk::IteratedShuffle(1, -1), std::invalid_argument);
  EXPECT_THROW(lk::IteratedShuffle(1, 40), std::invalid_argument); // 3^40 > 2^50
  EXPECT_THROW(lk::IteratedShuffle(1, 2, lk::ShuffleAxis::Cyclic, 0), std::invalid_argument);
}
