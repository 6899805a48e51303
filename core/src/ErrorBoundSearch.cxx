#include "latticekit/ErrorBoundSearch.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lk
{
namespace
{
bool usable(double e)
{
  return std::isfinite(e) && e > 0.0;
}
} // namespace

ErrorBoundSearchResult fewestWithinErrorBound(std::size_t lo, std::size_t hi, double bound,
  const std::function<bool(std::size_t, double&)>& error, const ErrorBoundSearchOptions& options)
{
  if (lo > hi)
    throw std::invalid_argument("the count range is empty");
  if (!(bound > 0.0) || !std::isfinite(bound))
    throw std::invalid_argument("the error bound must be a positive number");
  if (!(options.countTolerance >= 0.0) || !std::isfinite(options.countTolerance))
    throw std::invalid_argument("the count tolerance must be 0 or more");
  if (!(options.assumedExponent > 0.0) || !std::isfinite(options.assumedExponent))
    throw std::invalid_argument("the assumed exponent must be positive");

  ErrorBoundSearchResult result;
  // The bracket: `above` ends at the largest count measured above the bound
  // (lo - 1 notionally, its error unknown), `below` at the smallest measured
  // within it (hi notionally). A side's previous measurement gives a slope
  // while the other side is not measured yet.
  struct Side
  {
    double count = 0.0, error = NAN;         // the bracket's end
    double previousCount = 0.0, previousError = NAN;
    bool measured = false;
  };
  Side above, below;
  above.count = static_cast<double>(lo) - 1.0;
  below.count = static_cast<double>(hi);
  const double pAssumed = options.assumedExponent;
  int sameSide = 0, lastSide = 0; // +1: the last probe was within, -1: above

  // The exponent p of error ~ n^-p through a side's last two measurements,
  // kept to [0.5, 4]; the assumed one without two. Shallower slopes come from
  // plateaus of the max (one artefact's distance over a range of counts), and
  // an extrapolation on them overshoots far, where a fit costs the most.
  auto slope = [&](const Side& s) {
    if (!usable(s.previousError) || !usable(s.error) || s.previousCount <= 0.0 || s.previousCount == s.count)
      return pAssumed;
    const double q = std::log(s.previousError / s.error) / std::log(s.count / s.previousCount);
    return std::isfinite(q) ? std::clamp(q, 0.5, 4.0) : pAssumed;
  };
  // Halving: geometric while the ends are more than a factor 2 apart.
  auto halve = [](double f, double w) { return w > 2.0 * f ? std::sqrt(f * w) : 0.5 * (f + w); };
  auto record = [](Side& s, double n, double e) {
    s.previousCount = s.count;
    s.previousError = s.measured ? s.error : NAN;
    s.count = n;
    s.error = e;
    s.measured = true;
  };

  while (true)
  {
    const double w = below.count;
    const double width = std::max(1.0, options.countTolerance * w);
    if (w - above.count <= width || w <= static_cast<double>(lo))
      break;
    const double f = std::max(1.0, above.count);
    const bool aboveKnown = above.measured && usable(above.error);
    const bool belowKnown = below.measured && usable(below.error);
    double estimate;
    if (aboveKnown && belowKnown && above.error > below.error)
    {
      // Regula falsi on the log-log line through both ends.
      const double t = (std::log(above.error) - std::log(bound)) / (std::log(above.error) - std::log(below.error));
      estimate = std::exp(std::log(f) + t * (std::log(w) - std::log(f)));
      if (sameSide >= 3)
        estimate = halve(f, w);
      else if (sameSide == 2)
        estimate += lastSide < 0 ? 0.5 * width : -0.5 * width;
    }
    else if (aboveKnown && !below.measured)
    {
      // Only failures so far: extrapolate upwards; the step doubles (in log)
      // after the third failure in a row.
      estimate = f * std::pow(above.error / bound, 1.0 / slope(above));
      if (sameSide >= 3)
        estimate = f * (estimate / f) * (estimate / f);
    }
    else if (belowKnown && !above.measured)
    {
      estimate = w * std::pow(below.error / bound, 1.0 / slope(below));
      if (sameSide >= 3)
        estimate = w * (estimate / w) * (estimate / w);
    }
    else
      // Nothing usable (a first probe, errors of 0 or unmeasurable, or a
      // bracket whose ends are out of order).
      estimate = halve(f, w);
    // Strictly inside the bracket.
    const auto n = static_cast<std::size_t>(std::llround(std::clamp(estimate, above.count + 1.0, w - 1.0)));

    double e = NAN;
    if (!error(n, e))
    {
      result.aborted = true;
      break;
    }
    result.probes.emplace_back(n, e);
    const int side = (std::isfinite(e) && e <= bound) ? 1 : -1;
    sameSide = side == lastSide ? sameSide + 1 : 1;
    lastSide = side;
    record(side > 0 ? below : above, static_cast<double>(n), e);
  }
  result.count = static_cast<std::size_t>(below.count);
  result.withinBound = below.measured;
  return result;
}
} // namespace lk
