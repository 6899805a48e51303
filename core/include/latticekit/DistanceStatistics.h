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
  double mean = 0.0; ///< area-weighted over face samples (all samples if none)
  double rms = 0.0;  ///< area-weighted over face samples (all samples if none)
  double area = 0.0; ///< sum of the face sample weights
  std::size_t vertexSamples = 0;
  std::size_t edgeSamples = 0;
  std::size_t faceSamples = 0;
  std::size_t samples() const { return vertexSamples + edgeSamples + faceSamples; }
};

/// Summarises distances[i] of samples[i].
DistanceStatistics summarizeDistances(const SampleSet& samples, const std::vector<double>& distances);

/// The symmetric (two-sided) figures: each statistic is the worse of the two
/// directions, as the Hausdorff distance is the larger of the two one-sided ones.
DistanceStatistics symmetricStatistics(const DistanceStatistics& ab, const DistanceStatistics& ba);

} // namespace lk
