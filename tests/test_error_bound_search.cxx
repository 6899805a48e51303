#include "latticekit/ErrorBoundSearch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <stdexcept>

namespace
{
/// Plain bisection over [lo, hi] with hi taken to hold: the reference.
std::size_t bisect(std::size_t lo, std::size_t hi, const std::function<double(std::size_t)>& f, double bound, int& trials)
{
  trials = 0;
  while (lo < hi)
  {
    const std::size_t mid = lo + (hi - lo) / 2;
    ++trials;
    if (f(mid) <= bound)
      hi = mid;
    else
      lo = mid + 1;
  }
  return hi;
}

/// Every probe strictly inside the range, none twice.
void expectProbesInside(const lk::ErrorBoundSearchResult& r, std::size_t lo, std::size_t hi)
{
  std::set<std::size_t> seen;
  for (const auto& [n, e] : r.probes)
  {
    EXPECT_GE(n, lo);
    EXPECT_LT(n, hi);
    EXPECT_TRUE(seen.insert(n).second) << "count " << n << " probed twice";
  }
}
} // namespace

TEST(ErrorBoundSearch, FindsTheExactCountOfAPowerLawInFewerTrialsThanBisection)
{
  // The error of a fitted surface: about C n^-p. Several exponents, bounds
  // and ranges; exact search (tolerance 0).
  lk::ErrorBoundSearchOptions exact;
  exact.countTolerance = 0.0;
  int searchTrials = 0, bisectionTrials = 0;
  for (double p : { 0.7, 1.0, 1.6 })
    for (double bound : { 0.05, 0.2, 1.0 })
    {
      auto f = [p](std::size_t n) { return 60.0 * std::pow(static_cast<double>(n), -p); };
      const std::size_t lo = 4, hi = 12211;
      int trials = 0;
      const std::size_t reference = bisect(lo, hi, f, bound, trials);
      bisectionTrials += trials;
      const lk::ErrorBoundSearchResult r = lk::fewestWithinErrorBound(
        lo, hi, bound,
        [&](std::size_t n, double& e) {
          e = f(n);
          return true;
        },
        exact);
      EXPECT_EQ(r.count, reference) << "p " << p << ", bound " << bound;
      EXPECT_FALSE(r.aborted);
      EXPECT_EQ(r.withinBound, reference < hi);
      expectProbesInside(r, lo, hi);
      searchTrials += static_cast<int>(r.probes.size());
    }
  std::printf("9 searches: %d trials, bisection %d\n", searchTrials, bisectionTrials);
  EXPECT_LT(searchTrials * 2, bisectionTrials);
}

TEST(ErrorBoundSearch, StopsWithinTheCountToleranceOnANoisyError)
{
  // A max error is one point's distance: +-8 % noise on the power law, not
  // monotone. The count returned was measured within the bound, and a count
  // at most 1 % below it was measured above the bound.
  std::size_t total = 0;
  for (unsigned seed = 1; seed <= 20; ++seed)
  {
    auto f = [seed](std::size_t n) {
      const unsigned h = static_cast<unsigned>(n) * 2654435761u + seed * 40503u;
      const double noise = static_cast<double>(h % 1000) / 1000.0 * 0.16 - 0.08;
      return 40.0 * std::pow(static_cast<double>(n), -1.2) * (1.0 + noise);
    };
    const double bound = 0.01 + 0.004 * seed;
    const lk::ErrorBoundSearchResult r = lk::fewestWithinErrorBound(4, 12211, bound, [&](std::size_t n, double& e) {
      e = f(n);
      return true;
    });
    ASSERT_TRUE(r.withinBound);
    total += r.probes.size();
    EXPECT_LE(f(r.count), bound);
    bool bracketed = false;
    for (const auto& [n, e] : r.probes)
      bracketed |= e > bound && n < r.count && static_cast<double>(r.count - n) <= std::max(1.0, 0.01 * r.count);
    EXPECT_TRUE(bracketed) << "seed " << seed << ": count " << r.count;
    EXPECT_LE(r.probes.size(), 14u); // no worse than bisection over this range
    expectProbesInside(r, 4, 12211);
  }
  std::printf("20 noisy searches: %zu trials\n", total);
}

TEST(ErrorBoundSearch, FindsAStepExactly)
{
  // An error that jumps (the log-log line is useless there): the guards fall
  // back to halving the bracket.
  lk::ErrorBoundSearchOptions exact;
  exact.countTolerance = 0.0;
  const lk::ErrorBoundSearchResult r = lk::fewestWithinErrorBound(
    4, 5000, 0.5,
    [](std::size_t n, double& e) {
      e = n < 700 ? 1.0 : 0.1;
      return true;
    },
    exact);
  std::printf("step at 700: %zu trials\n", r.probes.size());
  EXPECT_EQ(r.count, 700u);
  EXPECT_TRUE(r.withinBound);
  EXPECT_LE(r.probes.size(), 20u);
  expectProbesInside(r, 4, 5000);
}

TEST(ErrorBoundSearch, ReportsWhenNothingIsWithinTheBound)
{
  const lk::ErrorBoundSearchResult r = lk::fewestWithinErrorBound(4, 100, 0.5, [](std::size_t, double& e) {
    e = 2.0;
    return true;
  });
  EXPECT_EQ(r.count, 100u);
  EXPECT_FALSE(r.withinBound);
  EXPECT_FALSE(r.probes.empty());
  // Unmeasurable trials (an empty surface) count as above the bound.
  const lk::ErrorBoundSearchResult nan = lk::fewestWithinErrorBound(4, 100, 0.5, [](std::size_t n, double& e) {
    e = n < 50 ? NAN : 0.1;
    return true;
  });
  EXPECT_GE(nan.count, 50u);
  EXPECT_LE(nan.count, 51u); // within 1 % (at least 1) of 50
  EXPECT_TRUE(nan.withinBound);
}

TEST(ErrorBoundSearch, StopsWhenAborted)
{
  int calls = 0;
  const lk::ErrorBoundSearchResult r = lk::fewestWithinErrorBound(4, 10000, 0.1, [&](std::size_t n, double& e) {
    e = 100.0 / static_cast<double>(n);
    return ++calls < 2;
  });
  EXPECT_TRUE(r.aborted);
  EXPECT_EQ(calls, 2);
  EXPECT_EQ(r.probes.size(), 1u);
}

TEST(ErrorBoundSearch, NeedsNoTrialWhenTheRangeHasOneCount)
{
  int calls = 0;
  const lk::ErrorBoundSearchResult r = lk::fewestWithinErrorBound(7, 7, 0.1, [&](std::size_t, double& e) {
    e = 1.0;
    ++calls;
    return true;
  });
  EXPECT_EQ(calls, 0);
  EXPECT_EQ(r.count, 7u);
  EXPECT_FALSE(r.withinBound);
}

TEST(ErrorBoundSearch, RefusesBadArguments)
{
  auto f = [](std::size_t, double& e) {
    e = 1.0;
    return true;
  };
  EXPECT_THROW(lk::fewestWithinErrorBound(10, 9, 0.1, f), std::invalid_argument);
  EXPECT_THROW(lk::fewestWithinErrorBound(4, 9, 0.0, f), std::invalid_argument);
  EXPECT_THROW(lk::fewestWithinErrorBound(4, 9, NAN, f), std::invalid_argument);
  EXPECT_THROW(lk::fewestWithinErrorBound(4, 9, INFINITY, f), std::invalid_argument);
  lk::ErrorBoundSearchOptions o;
  o.countTolerance = -0.1;
  EXPECT_THROW(lk::fewestWithinErrorBound(4, 9, 0.1, f, o), std::invalid_argument);
  o.countTolerance = 0.01;
  o.assumedExponent = 0.0;
  EXPECT_THROW(lk::fewestWithinErrorBound(4, 9, 0.1, f, o), std::invalid_argument);
}
