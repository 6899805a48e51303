#pragma once
/// \file PointHash.h
/// A hash of a point's three coordinates for hash tables that merge equal
/// points (exact equality, ==): the repair's point merge and the repair
/// filter's lookup of input points by position.

#include <cstddef>
#include <functional>

namespace lk
{
/// Agrees with == on each coordinate: -0.0 hashes as 0.0 (+0.0 turns the
/// one into the other), which it equals.
inline std::size_t hashCoordinates(double x, double y, double z)
{
  const std::hash<double> h;
  return h(x + 0.0) ^ (h(y + 0.0) * 0x9E3779B97F4A7C15ULL) ^ (h(z + 0.0) * 0xC2B2AE3D27D4EB4FULL);
}
} // namespace lk
