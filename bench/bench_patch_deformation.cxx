// Benchmark (not a test): one functional deformation (eq. 1 of seed 002) with
// adaptive refinement on a 100,352-triangle planar patch, then the
// conforming triangle list a renderer would draw (target: under 16 ms, one
// frame at 60 Hz). Anchor in the same run: vtkWarpScalar moving every point
// of the same patch along its normal (a full-pass VTK deformation, no
// refinement).
//
// usage: bench_patch_deformation
#include "latticekit/AdaptivePatchMesh.h"

#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkTriangleFilter.h>
#include <vtkWarpScalar.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

namespace
{
double ms(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}
} // namespace

int main()
{
  const int n = 224; // 2 n^2 = 100,352 triangles on [0, n]^2
  lk::TriangleMesh patch;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i)
      patch.points.emplace_back(i, j, 0.0);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
    {
      const int a = i + (n + 1) * j;
      patch.triangles.push_back({ { a, a + 1, a + n + 2 } });
      patch.triangles.push_back({ { a, a + n + 2, a + n + 1 } });
    }
  const auto t0 = std::chrono::steady_clock::now();
  lk::AdaptivePatchMesh mesh(patch, 4);
  const double setup = ms(t0);

  std::vector<double> times;
  std::size_t triangles = 0;
  for (int step = 0; step < 20; ++step)
  {
    // A new pick every frame, as a user dragging across the patch.
    const lk::Vec3 centre(60.0 + 5.3 * step, 80.0 + 3.1 * step, 0.0);
    const auto t1 = std::chrono::steady_clock::now();
    mesh.functionalDeformation(centre, 3.0, 0.08, 8.0, 0.02);
    triangles = mesh.triangles().size();
    times.push_back(ms(t1));
  }
  std::sort(times.begin(), times.end());

  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(n, n);
  vtkNew<vtkTriangleFilter> tri;
  tri->SetInputConnection(plane->GetOutputPort());
  tri->Update();
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetNumberOfTuples(tri->GetOutput()->GetNumberOfPoints());
  scalars->Fill(0.5);
  vtkNew<vtkPolyData> input;
  input->ShallowCopy(tri->GetOutput());
  input->GetPointData()->SetScalars(scalars);
  vtkNew<vtkWarpScalar> warp;
  warp->SetInputData(input);
  std::vector<double> anchor;
  for (int run = 0; run < 10; ++run)
  {
    warp->Modified();
    const auto t2 = std::chrono::steady_clock::now();
    warp->Update();
    anchor.push_back(ms(t2));
  }
  std::sort(anchor.begin(), anchor.end());
  std::printf("patch: %zu triangles, set-up %.1f ms (once)\n", patch.triangles.size(), setup);
  std::printf("functional deformation with refinement + conforming triangle list: median %.2f ms, max %.2f ms "
              "(target < 16 ms); after 20 picks %zu triangles, %zu splits\n",
    times[times.size() / 2], times.back(), triangles, mesh.splitCount());
  std::printf("vtkWarpScalar over the whole patch (%lld triangles): median %.2f ms; ratio %.2f\n",
    static_cast<long long>(input->GetNumberOfPolys()), anchor[anchor.size() / 2],
    times[times.size() / 2] / anchor[anchor.size() / 2]);
  return 0;
}
