#include "latticekit/DistanceStatistics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lk
{

void DistanceAccumulator::add(const SampleSet& samples, const double* distances)
{
  for (std::size_t i = 0; i < samples.size(); ++i)
  {
    const double d = distances[i];
    s_.max = std::max(s_.max, d);
    sum_ += d;
    sum2_ += d * d;
    switch (samples.kinds[i])
    {
      case SampleKind::Vertex:
        ++s_.vertexSamples;
        break;
      case SampleKind::Edge:
        ++s_.edgeSamples;
        break;
      case SampleKind::Face:
        ++s_.faceSamples;
        wsum_ += samples.weights[i];
        wd_ += samples.weights[i] * d;
        wd2_ += samples.weights[i] * d * d;
        break;
    }
  }
}

DistanceStatistics DistanceAccumulator::result(bool overAllSamples) const
{
  DistanceStatistics s = s_;
  s.area = wsum_;
  if (wsum_ > 0.0 && !overAllSamples)
  {
    s.mean = wd_ / wsum_;
    s.rms = std::sqrt(wd2_ / wsum_);
  }
  else if (s.samples() > 0)
  {
    const auto n = static_cast<double>(s.samples());
    s.mean = sum_ / n;
    s.rms = std::sqrt(sum2_ / n);
  }
  return s;
}

DistanceStatistics summarizeDistances(const SampleSet& samples, const std::vector<double>& distances, bool overAllSamples)
{
  if (distances.size() != samples.size())
  {
    throw std::invalid_argument("summarizeDistances: one distance per sample is needed");
  }
  DistanceAccumulator sums;
  sums.add(samples, distances.data());
  return sums.result(overAllSamples);
}

DistanceStatistics symmetricStatistics(const DistanceStatistics& ab, const DistanceStatistics& ba)
{
  DistanceStatistics s;
  s.max = std::max(ab.max, ba.max);
  s.mean = std::max(ab.mean, ba.mean);
  s.rms = std::max(ab.rms, ba.rms);
  s.area = ab.area + ba.area;
  s.vertexSamples = ab.vertexSamples + ba.vertexSamples;
  s.edgeSamples = ab.edgeSamples + ba.edgeSamples;
  s.faceSamples = ab.faceSamples + ba.faceSamples;
  return s;
}

} // namespace lk
