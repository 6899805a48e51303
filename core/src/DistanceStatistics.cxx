#include "latticekit/DistanceStatistics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace lk
{

DistanceStatistics summarizeDistances(const SampleSet& samples, const std::vector<double>& distances, bool overAllSamples)
{
  if (distances.size() != samples.size())
  {
    throw std::invalid_argument("summarizeDistances: one distance per sample is needed");
  }
  DistanceStatistics s;
  double wsum = 0.0, wd = 0.0, wd2 = 0.0;
  double sum = 0.0, sum2 = 0.0;
  for (std::size_t i = 0; i < distances.size(); ++i)
  {
    const double d = distances[i];
    s.max = std::max(s.max, d);
    sum += d;
    sum2 += d * d;
    switch (samples.kinds[i])
    {
      case SampleKind::Vertex:
        ++s.vertexSamples;
        break;
      case SampleKind::Edge:
        ++s.edgeSamples;
        break;
      case SampleKind::Face:
        ++s.faceSamples;
        wsum += samples.weights[i];
        wd += samples.weights[i] * d;
        wd2 += samples.weights[i] * d * d;
        break;
    }
  }
  s.area = wsum;
  if (wsum > 0.0 && !overAllSamples)
  {
    s.mean = wd / wsum;
    s.rms = std::sqrt(wd2 / wsum);
  }
  else if (!distances.empty())
  {
    const auto n = static_cast<double>(distances.size());
    s.mean = sum / n;
    s.rms = std::sqrt(sum2 / n);
  }
  return s;
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
