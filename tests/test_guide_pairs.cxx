// Which saw lines' guides are joined (apps/common/GuidePairs): chains of the
// lines either side of each piece, as they lie along the bone, not as drawn.
#include "common/GuidePairs.h"

#include "TestSupport.h"
#include "vtkLKCuttingGuideFilter.h"
#include "vtkLKGuideBarFilter.h"

#include <gtest/gtest.h>

#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
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
using Chains = std::vector<std::vector<std::size_t>>;

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

/// The cutting guide of the plane through `origin` with normal `normal`
/// on `bone`, put on along `approach` (not yet updated: a pipeline input).
vtkSmartPointer<vtkLKCuttingGuideFilter> guideFilter(
  vtkPolyData* bone, const double origin[3], const double normal[3], const double approach[3])
{
  auto guide = vtkSmartPointer<vtkLKCuttingGuideFilter>::New();
  guide->SetInputData(bone);
  guide->SetPlaneOrigin(origin);
  guide->SetPlaneNormal(normal);
  guide->SetApproach(approach);
  return guide;
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

TEST(GuidePairs, LinesDrawnInOrderAlongTheBoneJoinAsDrawn)
{
  EXPECT_EQ(lkapp::chainLinesByPiece(chain({ 0, 1 })), (Chains{ { 0, 1 } }));
  EXPECT_EQ(lkapp::chainLinesByPiece(chain({ 0, 1, 2 })), (Chains{ { 0, 1, 2 } }));
  EXPECT_EQ(lkapp::chainLinesByPiece(chain({ 0, 1, 2, 3 })), (Chains{ { 0, 1, 2, 3 } }));
}

TEST(GuidePairs, LinesDrawnOutOfOrderJoinAsTheyLie)
{
  // A chin cut (the 3rd line) drawn after the two body cuts: in the middle.
  const auto piecesOf = chain({ 0, 2, 1 });
  EXPECT_EQ(lkapp::chainLinesByPiece(piecesOf), (Chains{ { 0, 2, 1 } }));
  EXPECT_EQ(lkapp::lineNeighbours(1, piecesOf), (std::vector<std::size_t>{ 2 }));
  EXPECT_EQ(lkapp::lineNeighbours(2, piecesOf), (std::vector<std::size_t>{ 0, 1 }));
  // Four in the order 3 1 2 4 along the bone, and 4 2 1 3: from the end with
  // the smaller number.
  EXPECT_EQ(lkapp::chainLinesByPiece(chain({ 2, 0, 1, 3 })), (Chains{ { 2, 0, 1, 3 } }));
  EXPECT_EQ(lkapp::chainLinesByPiece(chain({ 3, 1, 0, 2 })), (Chains{ { 2, 0, 1, 3 } }));
}

TEST(GuidePairs, APieceBetweenThreeLinesJoinsTwoAndARingIsNotClosed)
{
  // A ramus (piece 0) with its condyle (line 1) and coronoid (line 2) cut
  // off and the body cut at line 3, the body cut again further on (line 4):
  // the body's piece joins lines 3 and 4; the ramus one more pair, 1 and 2.
  const std::vector<std::set<std::size_t>> ramus{ { 0, 1 }, { 0, 2 }, { 0, 3 }, { 3, 4 } };
  EXPECT_EQ(lkapp::chainLinesByPiece(ramus), (Chains{ { 0, 1 }, { 2, 3 } }));
  // A ring cut at three places: one chain of all three, not closed.
  const std::vector<std::set<std::size_t>> ring{ { 0, 1 }, { 1, 2 }, { 2, 0 } };
  const Chains rings = lkapp::chainLinesByPiece(ring);
  ASSERT_EQ(rings.size(), 1u);
  EXPECT_EQ(rings[0].size(), 3u);
  EXPECT_EQ(rings[0], (std::vector<std::size_t>{ 1, 0, 2 }));
}

TEST(GuidePairs, WithoutACutEveryLineIsOnTheBoneAndTheyJoinInPairsInOrder)
{
  const std::vector<std::set<std::size_t>> whole(5, std::set<std::size_t>{ 0 });
  EXPECT_EQ(lkapp::chainLinesByPiece(whole), (Chains{ { 0, 1 }, { 2, 3 } }));
  EXPECT_EQ(lkapp::lineNeighbours(4, whole), (std::vector<std::size_t>{ 0, 1, 2, 3 }));
}

TEST(GuidePairs, ALineOnNoPieceOrAloneIsNeverJoined)
{
  // Line 1 failed (on no piece); lines 0 and 2 bound pieces that share none.
  const std::vector<std::set<std::size_t>> piecesOf{ { 0, 1 }, {}, { 2, 3 } };
  EXPECT_TRUE(lkapp::chainLinesByPiece(piecesOf).empty());
  EXPECT_TRUE(lkapp::lineNeighbours(1, piecesOf).empty());
  EXPECT_TRUE(lkapp::lineNeighbours(0, piecesOf).empty());
  EXPECT_TRUE(lkapp::chainLinesByPiece({}).empty());
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
  // Alone on its pieces.
  const std::vector<std::set<std::size_t>> apart{ { 0, 1 }, { 2, 3 } };
  EXPECT_EQ(lkapp::whyLineStaysApart(1, apart, {}, "flat line", "line", number),
    "no other flat line bounds a piece of the cut with it (a resection guide joins the flat lines either side of "
    "one piece)");
  // Without a cut, five lines: the 5th beside all four, each joined.
  const std::vector<std::set<std::size_t>> whole(5, std::set<std::size_t>{ 0 });
  EXPECT_EQ(lkapp::whyLineStaysApart(4, whole, lkapp::chainLinesByPiece(whole), "saw line", "stroke", number),
    "the saw lines beside it (strokes 1, 2, 3 and 4) are joined to others there");
  // Three lines on one piece, the third left over.
  const std::vector<std::set<std::size_t>> three(3, std::set<std::size_t>{ 0 });
  EXPECT_EQ(lkapp::chainLinesByPiece(three), (Chains{ { 0, 1 } }));
  EXPECT_EQ(lkapp::whyLineStaysApart(2, three, lkapp::chainLinesByPiece(three), "saw line", "stroke", number),
    "the saw lines beside it (strokes 1 and 2) are joined to others there");
  // A line in a chain does not stay apart.
  EXPECT_EQ(lkapp::whyLineStaysApart(1, three, lkapp::chainLinesByPiece(three), "saw line", "stroke", number), "");
  EXPECT_EQ(lkapp::chainNumbers({ 0, 2, 1 }, number), "1, 3 and 2");
  EXPECT_EQ(lkapp::chainNumbers({ 3 }, number), "4");
}

namespace
{
using Runs = std::vector<std::pair<std::vector<std::size_t>, std::string>>;

Runs runsOf(const std::vector<lkapp::JoinedRun>& runs)
{
  Runs out;
  for (const auto& r : runs)
    out.emplace_back(r.lines, r.error);
  return out;
}

bool hasNeighbours(const std::vector<std::size_t>& lines, std::size_t a, std::size_t b)
{
  for (std::size_t k = 0; k + 1 < lines.size(); ++k)
    if (lines[k] == a && lines[k + 1] == b)
      return true;
  return false;
}
} // namespace

TEST(GuidePairs, AChainIsJoinedWholeOrSplitWhereTwoNeighboursCannotBe)
{
  std::vector<std::vector<std::size_t>> calls;
  auto all = [](std::size_t) { return true; };
  // Joined whole: one try.
  auto joins = [&](const std::vector<std::size_t>& lines) {
    calls.push_back(lines);
    return std::string();
  };
  EXPECT_EQ(runsOf(lkapp::joinChain({ 0, 2, 1 }, all, joins)), (Runs{ { { 0, 2, 1 }, "" } }));
  EXPECT_EQ(calls.size(), 1u);

  // Lines 1 and 2 too far apart: the whole fails, each two are tried, and
  // the chain is joined either side of them.
  calls.clear();
  auto farApart = [&](const std::vector<std::size_t>& lines) {
    calls.push_back(lines);
    return hasNeighbours(lines, 1, 2) ? std::string("too far") : std::string();
  };
  EXPECT_EQ(runsOf(lkapp::joinChain({ 0, 1, 2, 3 }, all, farApart)),
    (Runs{ { { 0, 1 }, "" }, { { 1, 2 }, "too far" }, { { 2, 3 }, "" } }));
  EXPECT_EQ(calls, (std::vector<std::vector<std::size_t>>{ { 0, 1, 2, 3 }, { 0, 1 }, { 1, 2 }, { 2, 3 } }));
  // The first two: the rest joined whole, tried once more.
  calls.clear();
  auto firstTwo = [&](const std::vector<std::size_t>& lines) {
    calls.push_back(lines);
    return hasNeighbours(lines, 0, 1) ? std::string("facing apart") : std::string();
  };
  EXPECT_EQ(runsOf(lkapp::joinChain({ 0, 1, 2, 3 }, all, firstTwo)),
    (Runs{ { { 0, 1 }, "facing apart" }, { { 1, 2, 3 }, "" } }));
  EXPECT_EQ(calls.back(), (std::vector<std::size_t>{ 1, 2, 3 }));
  // Two at a time but not three (no one direction to put three on): the
  // whole with its reason, not tried whole again, then pairs.
  calls.clear();
  auto pairsOnly = [&](const std::vector<std::size_t>& lines) {
    calls.push_back(lines);
    return lines.size() > 2 ? std::string("round the bone") : std::string();
  };
  EXPECT_EQ(runsOf(lkapp::joinChain({ 3, 0, 1, 2, 4 }, all, pairsOnly)),
    (Runs{ { { 3, 0, 1, 2, 4 }, "round the bone" }, { { 3, 0 }, "" }, { { 1, 2 }, "" } }));
  EXPECT_EQ(calls.size(), 1u + 4u + 2u); // the whole, the four pairs, 3-0-1 and 1-2-4
  // Up to three at a time: 3-0-1, then 2-4.
  calls.clear();
  auto upToThree = [&](const std::vector<std::size_t>& lines) {
    calls.push_back(lines);
    return lines.size() > 3 ? std::string("round the bone") : std::string();
  };
  EXPECT_EQ(runsOf(lkapp::joinChain({ 3, 0, 1, 2, 4 }, all, upToThree)),
    (Runs{ { { 3, 0, 1, 2, 4 }, "round the bone" }, { { 3, 0, 1 }, "" }, { { 2, 4 }, "" } }));
  // A line without a guide splits the chain; a run of one is no part.
  calls.clear();
  EXPECT_EQ(runsOf(lkapp::joinChain({ 0, 1, 2, 3, 4 }, [](std::size_t l) { return l != 2; }, joins)),
    (Runs{ { { 0, 1 }, "" }, { { 3, 4 }, "" } }));
  EXPECT_TRUE(lkapp::joinChain({ 0, 1, 2 }, [](std::size_t l) { return l == 1; }, joins).empty());
  // Two that cannot be joined: one try, its reason.
  calls.clear();
  EXPECT_EQ(runsOf(lkapp::joinChain({ 1, 2 }, all, farApart)), (Runs{ { { 1, 2 }, "too far" } }));
  EXPECT_EQ(calls.size(), 1u);
}

namespace
{
/// A 10 mm cube, finely triangulated, its centre at x = `centre`.
vtkSmartPointer<vtkPolyData> cubeAt(double centre)
{
  vtkNew<vtkTransform> move;
  move->Translate(centre, 0, 0);
  vtkNew<vtkTransformPolyDataFilter> moved;
  moved->SetInputData(lktest::triangulatedBox(10, 10, 10, 4));
  moved->SetTransform(move);
  moved->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->DeepCopy(moved->GetOutput());
  return out;
}
} // namespace

TEST(GuidePairs, TwoGuidesThatOverlapAreMeasuredAlongTheBone)
{
  // Cubes 7 mm apart overlap over 3 mm along x; 10 mm apart they touch; 12
  // mm apart they are apart.
  EXPECT_NEAR(lkapp::guidesOverlap(cubeAt(0), cubeAt(7)), 3.0, 1e-9);
  EXPECT_NEAR(lkapp::guidesOverlap(cubeAt(7), cubeAt(0)), 3.0, 1e-9);
  EXPECT_EQ(lkapp::guidesOverlap(cubeAt(0), cubeAt(10)), 0.0);
  EXPECT_EQ(lkapp::guidesOverlap(cubeAt(0), cubeAt(12)), 0.0);
  // Along the saw planes' normal, when the guides give it: here z, across
  // which the cubes (side by side along x) overlap over all 10 mm (less a
  // grid step, 0.625 mm, at each end: the points measured are the faces').
  auto a = cubeAt(0), b = cubeAt(7);
  for (vtkPolyData* part : { a.Get(), b.Get() })
  {
    vtkNew<vtkDoubleArray> normal;
    normal->SetName("GuidePlaneNormal");
    normal->SetNumberOfComponents(3);
    const double z[3] = { 0, 0, part == a.Get() ? 1.0 : -1.0 }; // either way round
    normal->InsertNextTuple(z);
    part->GetFieldData()->AddArray(normal);
  }
  EXPECT_NEAR(lkapp::guidesOverlap(a, b), 10.0 - 2 * 0.625, 1e-9);
  // A plan's guides, one not made: the pair that overlaps, by index.
  auto c = cubeAt(0), d = cubeAt(7), e = cubeAt(30);
  const std::vector<lkapp::GuideOverlap> overlaps = lkapp::overlappingGuides({ c, nullptr, d, e });
  ASSERT_EQ(overlaps.size(), 1u);
  EXPECT_EQ(overlaps[0].first, 0u);
  EXPECT_EQ(overlaps[0].second, 2u);
  EXPECT_NEAR(overlaps[0].along, 3.0, 1e-9);
  EXPECT_TRUE(lkapp::overlappingGuides({ c, e }).empty());
  // Nothing to measure.
  EXPECT_EQ(lkapp::guidesOverlap(a, nullptr), 0.0);
  EXPECT_EQ(lkapp::guidesOverlap(vtkSmartPointer<vtkPolyData>::New(), b), 0.0);
}

TEST(GuidePairs, TheBarFiltersGuideNumbersAreSaidAsTheLinesTheyAreOn)
{
  auto number = [](std::size_t line) { return std::to_string(line + 1); };
  const std::vector<std::size_t> lines{ 3, 0, 2 }; // strokes 4, 1 and 3, in that order
  EXPECT_EQ(lkapp::guidesByLine("Cannot join the guides: guide 1's contact still faces 19.6 degrees back", lines,
              "stroke", number),
    "guide of stroke 4's contact still faces 19.6 degrees back");
  EXPECT_EQ(lkapp::guidesByLine("guides 1 and 3 lie on one side of guide 2's slot", lines, "line", number),
    "guides of lines 4 and 3 lie on one side of guide of line 1's slot");
  EXPECT_EQ(lkapp::guidesByLine("guides 2 and 3: their slots are 0 mm apart (they reach 8 and 8 mm)", lines, "stroke",
              number),
    "guides of strokes 1 and 3: their slots are 0 mm apart (they reach 8 and 8 mm)");
  // Nothing to name, or a number it has no line for.
  EXPECT_EQ(lkapp::guidesByLine("a bar joins two guides, and port 1 has 1", lines, "stroke", number),
    "a bar joins two guides, and port 1 has 1");
  EXPECT_EQ(lkapp::guidesByLine("guide 7 has no GuideApproach", lines, "stroke", number),
    "guide of stroke ? has no GuideApproach");
}

TEST(GuidePairs, AJoinIsSaidAsItsBarsItsMergedBlocksOrBoth)
{
  // A 100 x 20 x 30 mm box, saw planes across it at x = -40, -3 and 3: the
  // first guide joined to the second by a bar, the second and third (6 mm
  // apart, overlapping) merged into one block.
  vtkSmartPointer<vtkPolyData> box = lktest::triangulatedBox(100, 20, 30, 3);
  std::vector<vtkSmartPointer<vtkLKCuttingGuideFilter>> guides;
  for (const double x : { -40.0, -3.0, 3.0 })
  {
    const double origin[3] = { x, 0, 0 }, normal[3] = { 1, 0, 0 }, front[3] = { 0, -1, 0 };
    vtkSmartPointer<vtkLKCuttingGuideFilter> guide = guideFilter(box, origin, normal, front);
    guide->Update();
    ASSERT_GT(guide->GetOutput()->GetNumberOfCells(), 0) << x;
    guides.push_back(guide);
  }
  auto number = [](std::size_t line) { return std::to_string(line + 1); };
  vtkNew<vtkLKGuideBarFilter> all;
  all->SetInputData(0, box);
  for (const auto& guide : guides)
    all->AddGuideConnection(guide->GetOutputPort());
  all->Update();
  ASSERT_EQ(all->GetNumberOfBars(), 1);
  ASSERT_EQ(all->GetNumberOfMerges(), 1);
  const std::string both = lkapp::joinText(all, { 0, 1, 2 }, "stroke", number);
  EXPECT_EQ(both.rfind("joined by a bar of 4.0 mm, ", 0), 0u) << both;
  EXPECT_NE(both.find(" mm clear of the bone between them, those of strokes 2 and 3 merged into one block (they "
                      "overlap; every slot and screw hole open through it)"),
    std::string::npos)
    << both;
  vtkNew<vtkLKGuideBarFilter> pair;
  pair->SetInputData(0, box);
  pair->AddGuideConnection(guides[1]->GetOutputPort());
  pair->AddGuideConnection(guides[2]->GetOutputPort());
  pair->Update();
  EXPECT_EQ(lkapp::joinText(pair, { 4, 2 }, "line", number),
    "merged into one block (they overlap; every slot and screw hole open through it)");
  vtkNew<vtkLKGuideBarFilter> barred;
  barred->SetInputData(0, box);
  barred->AddGuideConnection(guides[0]->GetOutputPort());
  barred->AddGuideConnection(guides[1]->GetOutputPort());
  barred->Update();
  const std::string bar = lkapp::joinText(barred, { 0, 1 }, "stroke", number);
  EXPECT_EQ(bar.rfind("joined by a bar of 4.0 mm, ", 0), 0u) << bar;
  EXPECT_EQ(bar.find("merged"), std::string::npos) << bar;
}

TEST(GuidePairs, GuidesThatCrossApartInTheChainAreSaid)
{
  // A V on the front of a 100 x 20 x 30 mm box (saw planes tilted 39
  // degrees either way, their guides overlapping at its point) and a guide
  // on the top between its arms, given between them: two bars, and the
  // arms' guides cut by each other's slots.
  vtkSmartPointer<vtkPolyData> box = lktest::triangulatedBox(100, 20, 30, 3);
  const double origins[3][3] = { { -14, 0, 0 }, { 0, 0, 0 }, { 14, 0, 0 } };
  const double normals[3][3] = { { 1, 0, 0.8 }, { 1, 0, 0 }, { 1, 0, -0.8 } };
  const double approaches[3][3] = { { 0, -1, 0 }, { 0, 0, 1 }, { 0, -1, 0 } };
  vtkNew<vtkLKGuideBarFilter> all;
  all->SetInputData(0, box);
  std::vector<vtkSmartPointer<vtkLKCuttingGuideFilter>> guides;
  for (int g = 0; g < 3; ++g)
  {
    vtkSmartPointer<vtkLKCuttingGuideFilter> guide = guideFilter(box, origins[g], normals[g], approaches[g]);
    guides.push_back(guide);
    all->AddGuideConnection(guide->GetOutputPort());
  }
  all->Update();
  ASSERT_EQ(all->GetNumberOfBars(), 2);
  ASSERT_EQ(all->GetNumberOfCrossings(), 1);
  auto number = [](std::size_t line) { return std::to_string(line + 1); };
  const std::string said = lkapp::joinText(all, { 4, 0, 2 }, "line", number);
  EXPECT_EQ(said.rfind("joined by 2 bars of 4.0 mm, ", 0), 0u) << said;
  EXPECT_NE(said.find(" clear of the bone between them; the guides of lines 5 and 3 overlap where their saw planes "
                      "cross near the bone, each cut by the other's slot and screw holes"),
    std::string::npos)
    << said;
  EXPECT_EQ(said.find("merged"), std::string::npos) << said;
}
