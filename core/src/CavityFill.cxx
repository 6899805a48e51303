#include "latticekit/CavityFill.h"

#include <stdexcept>

namespace lk
{
namespace
{
/// Marks (in `outside`) the background reachable from the seeds by steps to
/// face neighbours inside the box [0, n) (a slice when n[2] == 1).
void flood(const std::vector<char>& background, const int n[3], std::size_t offset, std::vector<std::size_t>& stack,
  std::vector<char>& outside)
{
  auto index = [&](int i, int j, int k) {
    return offset + static_cast<std::size_t>(i) +
      static_cast<std::size_t>(n[0]) * (static_cast<std::size_t>(j) + static_cast<std::size_t>(n[1]) * static_cast<std::size_t>(k));
  };
  auto push = [&](int i, int j, int k) {
    const std::size_t v = index(i, j, k);
    if (background[v] && !outside[v])
    {
      outside[v] = 1;
      stack.push_back(v);
    }
  };
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
        if (i == 0 || j == 0 || i == n[0] - 1 || j == n[1] - 1 || (n[2] > 1 && (k == 0 || k == n[2] - 1)))
          push(i, j, k);
  const std::size_t sy = static_cast<std::size_t>(n[0]), sz = sy * static_cast<std::size_t>(n[1]);
  while (!stack.empty())
  {
    const std::size_t v = stack.back();
    stack.pop_back();
    const std::size_t local = v - offset;
    const int i = static_cast<int>(local % sy), j = static_cast<int>((local / sy) % static_cast<std::size_t>(n[1])),
              k = static_cast<int>(local / sz);
    if (i > 0)
      push(i - 1, j, k);
    if (i + 1 < n[0])
      push(i + 1, j, k);
    if (j > 0)
      push(i, j - 1, k);
    if (j + 1 < n[1])
      push(i, j + 1, k);
    if (k > 0)
      push(i, j, k - 1);
    if (k + 1 < n[2])
      push(i, j, k + 1);
  }
}
} // namespace

std::vector<char> enclosedBackground(const std::vector<char>& background, int nx, int ny, int nz, bool perSlice)
{
  if (nx < 1 || ny < 1 || nz < 1 ||
    background.size() != static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny) * static_cast<std::size_t>(nz))
    throw std::invalid_argument("the background flags must be one per voxel of the given size");
  std::vector<std::size_t> stack;
  std::vector<char> outside(background.size(), 0);
  const int whole[3] = { nx, ny, nz };
  flood(background, whole, 0, stack, outside);
  std::vector<char> enclosed(background.size(), 0);
  for (std::size_t v = 0; v < background.size(); ++v)
    enclosed[v] = background[v] && !outside[v];
  if (perSlice)
  {
    std::vector<char> sliceOutside(background.size(), 0);
    const int slice[3] = { nx, ny, 1 };
    const std::size_t area = static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny);
    for (int k = 0; k < nz; ++k)
      flood(background, slice, area * static_cast<std::size_t>(k), stack, sliceOutside);
    for (std::size_t v = 0; v < background.size(); ++v)
      enclosed[v] = enclosed[v] || (background[v] && !sliceOutside[v]);
  }
  return enclosed;
}
} // namespace lk
