#pragma once
/// \file ErrorBoundSearch.h
/// The fewest vertices (or any count) whose error stays within a bound, when
/// each trial is expensive: a fit and a Metro measure, 10-20 s with the
/// refinement. Plain bisection over [4, n) needs log2(n) trials (14 on a
/// 12,000-vertex mandible). The error of a fitted surface falls roughly as a
/// power of the count (h^2 ~ 1/n for a smooth surface against its samples),
/// so the count where it crosses the bound is estimated on a log-log line:
/// through the two measured ends of the bracket when both are known (regula
/// falsi in log-log); from one end when only one is, with the slope of that
/// side's last two measurements (kept to exponents 0.5 to 4) or the assumed
/// exponent before there are two. Guards keep it from stalling: after two
/// estimates on the same side the next one is pushed half the stopping width
/// past the estimate (so that it tends to land on the other side), and after
/// three the bracket is halved (geometrically while its ends are more than a
/// factor 2 apart), or, while only one side is measured, the extrapolated step
/// doubles. Every probe lies strictly inside the bracket, so the search ends.
///
/// It stops when the bracket (the largest count measured above the bound, the
/// smallest within it) is no wider than `countTolerance` of the count (at
/// least 1, which is exact). The error is not monotone in the count (it is one
/// point's distance), so the answer is the fewest to within that tolerance
/// under the assumption that it is; the count returned was measured within
/// the bound unless no probe was.
#include <cstddef>
#include <functional>
#include <utility>
#include <vector>

namespace lk
{
struct ErrorBoundSearchOptions
{
  /// Stop when the bracket is at most this fraction of the count wide (at
  /// least 1). 0: exact (under monotonicity).
  double countTolerance = 0.01;
  /// Exponent p of error ~ count^-p used before two measurements give it.
  double assumedExponent = 1.0;
};

struct ErrorBoundSearchResult
{
  /// The count: the smallest measured within the bound, or `hi` (not
  /// measured) when none was.
  std::size_t count = 0;
  /// Whether `count` was measured within the bound.
  bool withinBound = false;
  /// The error callback asked to stop.
  bool aborted = false;
  /// Every probe in order: count and measured error.
  std::vector<std::pair<std::size_t, double>> probes;
};

/// `error(n, e)` measures count n and stores its error in e (infinity or NaN
/// when nothing can be measured: counted as above the bound); it returns false
/// to abort. Counts are searched in [lo, hi]; `hi` itself is taken to be
/// within the bound without a measurement. Throws std::invalid_argument when
/// lo > hi, the bound is not a positive finite number or an option is out of
/// range.
ErrorBoundSearchResult fewestWithinErrorBound(std::size_t lo, std::size_t hi, double bound,
  const std::function<bool(std::size_t, double&)>& error, const ErrorBoundSearchOptions& options = {});
} // namespace lk
