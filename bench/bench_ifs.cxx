// Benchmark (not a test): Bezier points per second from the IFS (chaos game
// and deterministic algorithm) against direct de Casteljau evaluation of the
// same number of points (the anchor, same run), for the cubic curve and the
// bicubic patch.
#include "latticekit/BezierIFS.h"

#include <chrono>
#include <cmath>
#include <cstdio>

int main()
{
  using Clock = std::chrono::steady_clock;
  auto seconds = [](Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); };
  const std::vector<lk::Vec3> cubic = { { 0, 0, 0 }, { 1, 2, 0 }, { 3, 2, 1 }, { 4, 0, 0 } };
  std::vector<lk::Vec3> net;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j)
      net.emplace_back(i, j, std::sin(i + 2.0 * j));
  const std::size_t N = 2000000;
  volatile double sink = 0.0;

  {
    const auto maps = lk::bernsteinCurveMaps(3, { 0.5 });
    auto t0 = Clock::now();
    const auto chaos = lk::chaosGame(maps, { 0.5, 0.5 }, lk::bernsteinCurve(3, 0), { 0, 0 }, N, 1, cubic);
    const double tc = seconds(t0);
    t0 = Clock::now();
    const auto det = lk::deterministicIfs(maps, { lk::bernsteinCurve(3, 0), lk::bernsteinCurve(3, 1) },
      { { 0, 0 }, { 1, 0 } }, 20, cubic);
    const double td = seconds(t0);
    t0 = Clock::now();
    for (std::size_t i = 0; i < N; ++i)
      sink = sink + lk::deCasteljau(cubic, double(i) / N).x();
    const double tz = seconds(t0);
    std::printf("cubic curve: chaos game %.2f M points/s, deterministic %.2f M points/s, de Casteljau %.2f M "
                "points/s; ratios %.2f and %.2f\n",
      N / tc / 1e6, det.points.size() / td / 1e6, N / tz / 1e6, (N / tc) / (N / tz),
      (det.points.size() / td) / (N / tz));
  }
  {
    const auto maps = lk::bernsteinSurfaceMaps(3, 3, { 0.5 });
    auto t0 = Clock::now();
    const auto chaos = lk::chaosGame(maps, { 0.25, 0.25, 0.25, 0.25 }, lk::bernsteinSurface(3, 3, 0, 0), { 0, 0 },
      N / 4, 1, net);
    const double tc = seconds(t0);
    t0 = Clock::now();
    for (std::size_t i = 0; i < N / 4; ++i)
      sink = sink + lk::deCasteljauSurface(net, 3, 3, double(i % 1000) / 1000, double(i / 1000) / (N / 4000)).x();
    const double tz = seconds(t0);
    std::printf("bicubic patch: chaos game %.2f M points/s, de Casteljau %.2f M points/s; ratio %.2f\n",
      (N / 4) / tc / 1e6, (N / 4) / tz / 1e6, ((N / 4) / tc) / ((N / 4) / tz));
  }
  return sink > 1e300 ? 1 : 0;
}
