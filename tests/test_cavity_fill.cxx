#include "latticekit/CavityFill.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

namespace
{
/// An n x n x nz volume whose foreground is a square ring (Chebyshev distance
/// 2 from the centre) across the two axes given, in every layer of the third.
std::vector<char> squarePipe(int n, int nz, bool alongK)
{
  std::vector<char> background(static_cast<std::size_t>(n * n * nz), 1);
  const int c = n / 2;
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const int a = alongK ? i : j, b = alongK ? j : k; // the ring's two axes
        if (std::max(std::abs(a - c), std::abs(b - (alongK ? c : nz / 2))) == 2)
          background[static_cast<std::size_t>(i + n * (j + n * k))] = 0;
      }
  return background;
}

std::size_t count(const std::vector<char>& flags)
{
  return static_cast<std::size_t>(std::count(flags.begin(), flags.end(), 1));
}
} // namespace

TEST(CavityFill, TheInsideOfAHollowCubeIsEnclosed)
{
  // 7^3 voxels; the shell at Chebyshev distance 2 from the centre encloses 3^3.
  std::vector<char> background(343, 1);
  for (int k = 0; k < 7; ++k)
    for (int j = 0; j < 7; ++j)
      for (int i = 0; i < 7; ++i)
        if (std::max({ std::abs(i - 3), std::abs(j - 3), std::abs(k - 3) }) == 2)
          background[static_cast<std::size_t>(i + 7 * (j + 7 * k))] = 0;
  for (const bool perSlice : { false, true })
  {
    const std::vector<char> enclosed = lk::enclosedBackground(background, 7, 7, 7, perSlice);
    EXPECT_EQ(count(enclosed), 27u);
    EXPECT_EQ(enclosed[3 + 7 * (3 + 7 * 3)], 1); // the centre
    EXPECT_EQ(enclosed[0], 0);                   // a corner, outside
    EXPECT_EQ(enclosed[1 + 7 * (3 + 7 * 3)], 0); // the shell is foreground, not enclosed background
  }
}

TEST(CavityFill, APipeAlongTheSliceAxisIsEnclosedOnlySliceBySlice)
{
  // Open at both ends (k = 0 and k = 4): in 3D its inside reaches the border.
  const std::vector<char> pipe = squarePipe(7, 5, true);
  EXPECT_EQ(count(lk::enclosedBackground(pipe, 7, 7, 5, false)), 0u);
  EXPECT_EQ(count(lk::enclosedBackground(pipe, 7, 7, 5, true)), 9u * 5u);
}

TEST(CavityFill, APipeAcrossTheSlicesIsNotEnclosed)
{
  // Along i: within each slice k its inside is a strip that reaches the
  // slice's border, and in 3D the pipe's ends are open.
  const std::vector<char> pipe = squarePipe(7, 7, false);
  EXPECT_EQ(count(lk::enclosedBackground(pipe, 7, 7, 7, true)), 0u);
}

TEST(CavityFill, SizesThatDoNotMatchAreRefused)
{
  EXPECT_THROW(lk::enclosedBackground(std::vector<char>(10, 1), 2, 2, 2, true), std::invalid_argument);
  EXPECT_THROW(lk::enclosedBackground({}, 0, 1, 1, false), std::invalid_argument);
}
