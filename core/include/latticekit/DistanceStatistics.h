#pragma once
/// \file DistanceStatistics.h
/// Max, mean and RMS of sampled distances, Metro-style.

#include "latticekit/SurfaceSampling.h"

#include <vector>

namespace lk
{

struct DistanceStatistics
{
  double max = 0.0;  ///< over every sample (vertex, edge, face)
  double mean = 0.0; ///< area-weighted over face samples (all samples if none, or if asked)
  double rms = 0.0;  ///< area-weighted over face samples (all samples if none, or if asked)
  double area = 0.0; ///< sum of the face sample weights
  std::size_t vertexSamples = 0;
  std::size_t edgeSamples = 0;
  std::size_t faceSamples = 0;
  std::size_t samples() const { return vertexSamples + edgeSamples + faceSamples; }
};

/// Summarises distances[i] of samples[i]. With overAllSamples the mean and
/// RMS count every sample once, vertex, edge and face alike, as Metro 4
/// prints them; by default they are area-weighted over the face samples (a
/// surface integral, which does not depend on how many vertex and edge
/// samples there are).
DistanceStatistics summarizeDistances(
  const SampleSet& samples, const std::vector<double>& distances, bool overAllSamples = false);

/// The sums behind summarizeDistances, fed a block of samples at a time (a
/// sample set too large to hold at once, measured block by block). Blocks
/// added in the samples' order give the same figures, to the last bit, as
/// one call over all of them.
class DistanceAccumulator
{
public:
  /// Adds distances[i] of samples[i], one per sample of the set.
  void add(const SampleSet& samples, const double* distances);
  DistanceStatistics result(bool overAllSamples = false) const;

private:
  DistanceStatistics s_;
  double wsum_ = 0.0, wd_ = 0.0, wd2_ = 0.0; ///< face samples, area-weighted
  double sum_ = 0.0, sum2_ = 0.0;           ///< every sample
};

/// The symmetric (two-sided) figures: each statistic is the worse of the two
/// directions, as the Hausdorff distance is the larger of the two one-sided ones.
DistanceStatistics symmetricStatistics(const DistanceStatistics& ab, const DistanceStatistics& ba);

} // namespace lk
