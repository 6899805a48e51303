#include "latticekit/IteratedShuffle.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace lk
{

IteratedShuffle::IteratedShuffle(int shuffleCount, int iterations, ShuffleAxis axis, int baseIntervals)
  : M_(shuffleCount)
  , K_(iterations)
  , n_(2 * shuffleCount + 1)
  , N_(baseIntervals)
  , nK_(1)
  , axis_(axis)
{
  if (shuffleCount < 0)
    throw std::invalid_argument("the shuffle count M must be 0 or more, not " + std::to_string(shuffleCount));
  if (iterations < 0)
    throw std::invalid_argument("the iteration count K must be 0 or more, not " + std::to_string(iterations));
  if (iterations > 60)
    throw std::invalid_argument("the iteration count K must be 60 or less, not " + std::to_string(iterations));
  for (int k = 0; k < K_; ++k)
  {
    if (nK_ > (std::int64_t(1) << 50) / n_)
      throw std::invalid_argument("(2M + 1)^K is beyond double precision (M " + std::to_string(M_) + ", K " +
        std::to_string(K_) + "); use fewer iterations");
    nK_ *= n_;
  }
  if (axis == ShuffleAxis::Cyclic && baseIntervals < 1)
    throw std::invalid_argument("a cyclic axis needs at least one base interval");
}

std::int64_t IteratedShuffle::wrap(std::int64_t base) const
{
  if (axis_ != ShuffleAxis::Cyclic)
    return base;
  const std::int64_t r = base % N_;
  return r < 0 ? r + N_ : r;
}

ShuffleLabel IteratedShuffle::forward(const ShuffleLabel& s) const
{
  ShuffleLabel t;
  t.digits.resize(K_);
  if (K_ == 0)
  {
    t.base = wrap(s.base);
    return t;
  }
  t.base = wrap(s.base + M_ - s.digits[0]);
  for (int k = 0; k + 1 < K_; ++k)
    t.digits[k] = ((s.digits[k] - s.digits[k + 1] + M_) % n_ + n_) % n_;
  t.digits[K_ - 1] = s.digits[K_ - 1];
  return t;
}

ShuffleLabel IteratedShuffle::inverse(const ShuffleLabel& t) const
{
  ShuffleLabel s;
  s.digits.resize(K_);
  if (K_ == 0)
  {
    s.base = wrap(t.base);
    return s;
  }
  s.digits[K_ - 1] = t.digits[K_ - 1];
  for (int k = K_ - 2; k >= 0; --k)
    s.digits[k] = (t.digits[k] + s.digits[k + 1] - M_ + n_) % n_;
  s.base = wrap(t.base - M_ + s.digits[0]);
  return s;
}

ShuffleLabel IteratedShuffle::labelOf(double x) const
{
  ShuffleLabel l;
  const double b = std::floor(x);
  l.base = static_cast<std::int64_t>(b);
  std::int64_t q = static_cast<std::int64_t>(std::floor((x - b) * static_cast<double>(nK_)));
  if (q >= nK_)
    q = nK_ - 1;
  if (q < 0)
    q = 0;
  l.digits.resize(K_);
  for (int k = K_ - 1; k >= 0; --k)
  {
    l.digits[k] = static_cast<int>(q % n_);
    q /= n_;
  }
  return l;
}

double IteratedShuffle::startOf(const ShuffleLabel& l) const
{
  std::int64_t q = 0;
  for (int d : l.digits)
    q = q * n_ + d;
  return static_cast<double>(l.base) + static_cast<double>(q) / static_cast<double>(nK_);
}

double IteratedShuffle::forward(double x) const
{
  const ShuffleLabel s = labelOf(x);
  return startOf(forward(s)) + (x - startOf(s));
}

double IteratedShuffle::inverse(double y) const
{
  // The same digit map as inverse(ShuffleLabel), without allocation: this
  // runs once per sample of a wrinkly surface.
  const double b = std::floor(y);
  const double scaled = (y - b) * static_cast<double>(nK_);
  std::int64_t q = static_cast<std::int64_t>(std::floor(scaled));
  if (q >= nK_)
    q = nK_ - 1;
  if (q < 0)
    q = 0;
  const double rest = scaled - static_cast<double>(q);
  int e[64];
  for (int k = K_ - 1; k >= 0; --k)
  {
    e[k] = static_cast<int>(q % n_);
    q /= n_;
  }
  std::int64_t base = static_cast<std::int64_t>(b);
  std::int64_t source = 0;
  if (K_ > 0)
  {
    int d = e[K_ - 1];
    std::int64_t place = n_;
    source = d;
    for (int k = K_ - 2; k >= 0; --k)
    {
      d = (e[k] + d - M_ + n_) % n_;
      source += d * place;
      place *= n_;
    }
    base = wrap(base - M_ + d);
  }
  else
    base = wrap(base);
  return static_cast<double>(base) + (static_cast<double>(source) + rest) / static_cast<double>(nK_);
}

double IteratedShuffle::mirrorInto(double x, double length)
{
  if (!(length > 0.0) || !std::isfinite(x))
    return 0.0;
  const double period = 2.0 * length;
  double r = std::fmod(x, period);
  if (r < 0.0)
    r += period;
  if (r >= length)
    r = period - r;
  // r == length only for x on an odd multiple: keep the half-open interval.
  return r >= length ? std::nextafter(length, 0.0) : r;
}

} // namespace lk
