// Benchmark (not a test): tessellating a wrinkly surface of about a million
// triangles (the paper needed 12 min 26 s to polygonise its figure 14 model
// on an SGI Octane; target here: under 1 s), against VTK's own tessellation
// of a parametric surface (vtkParametricFunctionSource on
// vtkParametricRandomHills) to the same triangle count, measured in the same
// run. Two nets: the 3-direction net (irregular, both IST orders blended) and
// a regular grid, K = 3, M_U = M_V = 1.
//
// usage: bench_wrinkly
#include "vtkLKWrinklyNetSource.h"
#include "vtkLKWrinklySurfaceFilter.h"

#include <vtkLogger.h>
#include <vtkNew.h>
#include <vtkParametricFunctionSource.h>
#include <vtkParametricRandomHills.h>
#include <vtkPolyData.h>

#include <chrono>
#include <cmath>
#include <cstdio>

namespace
{
double seconds(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double anchor(long long triangles)
{
  vtkNew<vtkParametricRandomHills> hills;
  vtkNew<vtkParametricFunctionSource> source;
  source->SetParametricFunction(hills);
  const int side = static_cast<int>(std::sqrt(triangles / 2.0));
  source->SetUResolution(side);
  source->SetVResolution(side);
  source->GenerateTextureCoordinatesOff();
  const auto t0 = std::chrono::steady_clock::now();
  source->Update();
  return seconds(t0);
}
} // namespace

int main()
{
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_ERROR);
  struct Case
  {
    const char* name;
    int type, size;
  };
  for (const Case& c : { Case{ "3-direction net", vtkLKWrinklyNetSource::Polygon, 11 },
         Case{ "regular net", vtkLKWrinklyNetSource::Regular, 28 } })
  {
    vtkNew<vtkLKWrinklyNetSource> net;
    net->SetNetType(c.type);
    net->SetSides(6);
    net->SetRings(c.size);
    net->SetCellsU(c.size);
    net->SetCellsV(c.size);
    net->Update();
    vtkNew<vtkLKWrinklySurfaceFilter> wrinkly;
    wrinkly->SetInputConnection(net->GetOutputPort());
    wrinkly->SetIterations(3);
    double best = 1e9;
    for (int run = 0; run < 3; ++run)
    {
      wrinkly->Modified();
      const auto t0 = std::chrono::steady_clock::now();
      wrinkly->Update();
      best = std::min(best, seconds(t0));
    }
    const long long triangles = wrinkly->GetOutput()->GetNumberOfPolys();
    double vtkBest = 1e9;
    for (int run = 0; run < 3; ++run)
      vtkBest = std::min(vtkBest, anchor(triangles));
    std::printf("%s (%lld control points): %lld triangles in %.3f s (%.2f M triangles/s, target < 1 s); "
                "vtkParametricFunctionSource, same count: %.3f s; ratio %.2f\n",
      c.name, static_cast<long long>(net->GetOutput()->GetNumberOfPoints()), triangles, best,
      triangles / best / 1e6, vtkBest, best / vtkBest);
  }
  return 0;
}
