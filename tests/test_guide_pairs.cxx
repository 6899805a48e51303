// Which saw lines' guides are joined (apps/common/GuidePairs): the lines on
// either side of one piece, as they lie along the bone, not as drawn.
#include "common/GuidePairs.h"

#include <gtest/gtest.h>

#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <array>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace
{
using Pairs = std::vector<std::pair<std::size_t, std::size_t>>;

/// The pieces along each line of a bone cut across in a chain: `order`
/// gives the lines as they lie along it (line order[k] between pieces k and
/// k + 1).
std::vector<std::set<std::size_t>> chain(const std::vector<std::size_t>& order)
{
  std::vector<std::set<std::size_t>> piecesOf(order.size());
  for (std::size_t k = 0; k < order.size(); ++k)
    piecesOf[order[k]] = { k, k + 1 };
  return piecesOf;
}

vtkSmartPointer<vtkPolyData> cloud(const std::vector<std::array<double, 3>>& points)
{
  vtkNew<vtkPoints> p;
  for (const auto& x : points)
    p->InsertNextPoint(x.data());
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(p);
  return out;
}
} // namespace

TEST(GuidePairs, LinesDrawnInOrderAlongTheBonePairAsDrawn)
{
  EXPECT_EQ(lkapp::pairLinesByPiece(chain({ 0, 1, 2, 3 })), (Pairs{ { 0, 1 }, { 2, 3 } }));
  // Three: the first two; the third has no partner left.
  EXPECT_EQ(lkapp::pairLinesByPiece(chain({ 0, 1, 2 })), (Pairs{ { 0, 1 } }));
}

TEST(GuidePairs, LinesDrawnOutOfOrderPairAsTheyLie)
{
  // A chin cut (the 3rd line) drawn after the two body cuts: the 1st joins
  // the chin's, the 2nd stays apart, beside the chin's line.
  const auto piecesOf = chain({ 0, 2, 1 });
  EXPECT_EQ(lkapp::pairLinesByPiece(piecesOf), (Pairs{ { 0, 2 } }));
  EXPECT_EQ(lkapp::lineNeighbours(1, piecesOf), (std::vector<std::size_t>{ 2 }));
  EXPECT_EQ(lkapp::lineNeighbours(2, piecesOf), (std::vector<std::size_t>{ 0, 1 }));
  // Four in the order 3 1 2 4 along the bone: pairing the 1st with its first
  // neighbour (the 2nd) would leave the 3rd and the 4th without one; the
  // chain's ends go first, so both pairs are made.
  EXPECT_EQ(lkapp::pairLinesByPiece(chain({ 2, 0, 1, 3 })), (Pairs{ { 0, 2 }, { 1, 3 } }));
  EXPECT_EQ(lkapp::pairLinesByPiece(chain({ 3, 1, 0, 2 })), (Pairs{ { 0, 2 }, { 1, 3 } }));
}

TEST(GuidePairs, WithoutACutEveryLineIsOnTheBoneAndTheyPairInOrder)
{
  const std::vector<std::set<std::size_t>> whole(5, std::set<std::size_t>{ 0 });
  EXPECT_EQ(lkapp::pairLinesByPiece(whole), (Pairs{ { 0, 1 }, { 2, 3 } }));
  EXPECT_EQ(lkapp::lineNeighbours(4, whole), (std::vector<std::size_t>{ 0, 1, 2, 3 }));
}

TEST(GuidePairs, ALineOnNoPieceOrAloneIsNeverPaired)
{
  // Line 1 failed (on no piece); lines 0 and 2 bound pieces that share none.
  const std::vector<std::set<std::size_t>> piecesOf{ { 0, 1 }, {}, { 2, 3 } };
  EXPECT_TRUE(lkapp::pairLinesByPiece(piecesOf).empty());
  EXPECT_TRUE(lkapp::lineNeighbours(1, piecesOf).empty());
  EXPECT_TRUE(lkapp::lineNeighbours(0, piecesOf).empty());
  EXPECT_TRUE(lkapp::pairLinesByPiece({}).empty());
}

TEST(GuidePairs, ALineIsOnThePiecesThatHoldMostOfItsPoints)
{
  // A square loop in the plane x = 0, copied into the two pieces either side
  // of it; a third piece holds one of its four points.
  const std::vector<std::array<double, 3>> loop{ { 0, 0, 0 }, { 0, 1, 0 }, { 0, 1, 1 }, { 0, 0, 1 } };
  auto left = cloud({ { 0, 0, 0 }, { 0, 1, 0 }, { 0, 1, 1 }, { 0, 0, 1 }, { -1, 0.5, 0.5 } });
  auto right = cloud({ { 1, 0.5, 0.5 }, { 0, 0, 0 }, { 0, 1, 0 }, { 0, 1, 1 }, { 0, 0, 1 } });
  auto other = cloud({ { 0, 0, 0 }, { 5, 5, 5 } });
  auto empty = vtkSmartPointer<vtkPolyData>::New();
  const std::vector<vtkPolyData*> pieces{ left, empty, other, right };
  const auto piecesOf = lkapp::piecesAlongLines(pieces, { loop }, 1e-6);
  ASSERT_EQ(piecesOf.size(), 1u);
  EXPECT_EQ(piecesOf[0], (std::set<std::size_t>{ 0, 3 }));
  // Half its points within the tolerance is enough; beyond it they are off.
  const std::vector<std::array<double, 3>> moved{ { 0, 0, 0 }, { 0, 1, 0 }, { 2e-6, 1, 1 }, { 2e-6, 0, 1 } };
  EXPECT_EQ(lkapp::piecesAlongLines(pieces, { moved }, 1e-6)[0], (std::set<std::size_t>{ 0, 3 }));
  const std::vector<std::array<double, 3>> off{ { 0, 0, 0 }, { 2e-6, 1, 0 }, { 2e-6, 1, 1 }, { 2e-6, 0, 1 } };
  EXPECT_TRUE(lkapp::piecesAlongLines(pieces, { off }, 1e-6)[0].empty());
  EXPECT_TRUE(lkapp::piecesAlongLines(pieces, { {} }, 1e-6)[0].empty());
}

TEST(GuidePairs, ALineLeftApartIsToldWhy)
{
  auto number = [](std::size_t line) { return std::to_string(line + 1); };
  // Drawn 1, 3, 2 along the bone: the 2nd stays apart beside the 3rd.
  const auto piecesOf = chain({ 0, 2, 1 });
  const Pairs pairs = lkapp::pairLinesByPiece(piecesOf);
  EXPECT_EQ(lkapp::whyLineStaysApart(1, piecesOf, pairs, "saw line", "stroke", number),
    "the saw line beside it (stroke 3) is joined to stroke 1");
  // Alone on its pieces.
  const std::vector<std::set<std::size_t>> apart{ { 0, 1 }, { 2, 3 } };
  EXPECT_EQ(lkapp::whyLineStaysApart(1, apart, {}, "flat line", "line", number),
    "no other flat line bounds a piece of the cut with it (a resection guide joins the flat lines either side of "
    "one piece)");
  // Without a cut, five lines: the 5th beside all four, each joined.
  const std::vector<std::set<std::size_t>> whole(5, std::set<std::size_t>{ 0 });
  EXPECT_EQ(lkapp::whyLineStaysApart(4, whole, lkapp::pairLinesByPiece(whole), "saw line", "stroke", number),
    "the saw lines beside it (strokes 1, 2, 3 and 4) are joined to others");
}
