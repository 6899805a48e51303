// Where the planner's captions stand (apps/common/LabelPlacement.h).
#include "common/LabelPlacement.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <vector>

namespace
{
const lkapp::LabelRoom Window{ 4.0, 4.0, 996.0, 746.0 };

struct Placed
{
  double x0, y0, x1, y1;
};

std::vector<Placed> boxesOf(const std::vector<lkapp::Label>& labels, const std::vector<std::array<double, 2>>& offsets)
{
  std::vector<Placed> boxes;
  for (std::size_t i = 0; i < labels.size(); ++i)
  {
    const double x = labels[i].at[0] + offsets[i][0], y = labels[i].at[1] + offsets[i][1];
    boxes.push_back({ x, y, x + labels[i].size[0], y + labels[i].size[1] });
  }
  return boxes;
}

bool overlap(const Placed& a, const Placed& b)
{
  return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

lkapp::Label name(double x, double y, double width = 300.0)
{
  return { { x, y }, { width, 18.0 }, { 20.0, 20.0 } };
}
} // namespace

TEST(LabelPlacement, LabelsApartKeepTheirPlacesBesideTheirPoints)
{
  const std::vector<lkapp::Label> labels{ name(100, 100), name(100, 400), { { 500, 300 }, { 80, 16 }, { 15, -30 } } };
  const auto offsets = lkapp::placeLabels(labels, Window);
  ASSERT_EQ(offsets.size(), 3u);
  for (std::size_t i = 0; i < labels.size(); ++i)
  {
    EXPECT_DOUBLE_EQ(offsets[i][0], labels[i].offset[0]);
    EXPECT_DOUBLE_EQ(offsets[i][1], labels[i].offset[1]);
  }
}

TEST(LabelPlacement, ALabelThatWouldPassTheRoomsEdgeStandsOnTheOtherSideOfItsPointOrInsideTheRoom)
{
  // Left of its point where there is room, as far from it as it would
  // stand right of it.
  auto offsets = lkapp::placeLabels({ name(900, 300) }, Window);
  EXPECT_DOUBLE_EQ(offsets[0][0], -20.0 - 300.0);
  EXPECT_DOUBLE_EQ(offsets[0][1], 20.0);
  // Room on neither side: it ends at the right edge.
  offsets = lkapp::placeLabels({ name(900, 300) }, { 650.0, 4.0, 996.0, 746.0 });
  EXPECT_DOUBLE_EQ(900.0 + offsets[0][0] + 300.0, 996.0);
  // Its point left of the room (behind the CT view): it starts at the
  // room's left.
  offsets = lkapp::placeLabels({ name(300, 300) }, { 400.0, 4.0, 996.0, 746.0 });
  EXPECT_DOUBLE_EQ(300.0 + offsets[0][0], 400.0);
  // Wider than the room: it starts at the room's left.
  offsets = lkapp::placeLabels({ name(900, 300, 400) }, { 650.0, 4.0, 996.0, 746.0 });
  EXPECT_DOUBLE_EQ(900.0 + offsets[0][0], 650.0);
}

TEST(LabelPlacement, TwoLabelsOfOnePointGoToItsTwoSides)
{
  const std::vector<lkapp::Label> labels{ name(500, 300), name(500, 300) };
  const auto offsets = lkapp::placeLabels(labels, Window);
  EXPECT_DOUBLE_EQ(offsets[0][0], 20.0);
  EXPECT_DOUBLE_EQ(offsets[1][0], -320.0); // the other side, at the same height
  EXPECT_DOUBLE_EQ(offsets[1][1], 20.0);
  const auto boxes = boxesOf(labels, offsets);
  EXPECT_FALSE(overlap(boxes[0], boxes[1]));
}

TEST(LabelPlacement, ManyLabelsOfNearPointsLieOverNoneAndStayInTheRoom)
{
  // The five-saw plan's six long names, their points within 40 pixels.
  std::vector<lkapp::Label> labels;
  for (int i = 0; i < 6; ++i)
    labels.push_back(name(480 + 8 * i, 350 - 6 * i, 330));
  labels.push_back({ { 490, 340 }, { 90, 16 }, { 15, -30 } }); // a measured value among them
  const auto offsets = lkapp::placeLabels(labels, Window);
  const auto boxes = boxesOf(labels, offsets);
  for (std::size_t i = 0; i < boxes.size(); ++i)
  {
    EXPECT_GE(boxes[i].x0, Window[0]);
    EXPECT_GE(boxes[i].y0, Window[1]);
    EXPECT_LE(boxes[i].x1, Window[2]);
    EXPECT_LE(boxes[i].y1, Window[3]);
    for (std::size_t j = 0; j < i; ++j)
      EXPECT_FALSE(overlap(boxes[i], boxes[j])) << "labels " << j << " and " << i;
    // Near its point: within a few lines of it.
    EXPECT_LT(std::abs(boxes[i].y0 - labels[i].at[1]), 100.0) << "label " << i;
  }
}

TEST(LabelPlacement, ALabelAboveTheTopStandsInsideTheRoom)
{
  const auto offsets = lkapp::placeLabels({ name(100, 740) }, Window);
  EXPECT_DOUBLE_EQ(740.0 + offsets[0][1] + 18.0, 746.0);
}

TEST(LabelPlacement, WithNoFreePlaceALabelKeepsItsFirstAndTheRestArePlaced)
{
  // A room one line high and as wide as one label: the second cannot be
  // apart from the first; it keeps its first place, and the third is placed.
  const lkapp::LabelRoom narrow{ 0.0, 0.0, 330.0, 20.0 };
  const std::vector<lkapp::Label> labels{ name(0, 0), name(0, 0), { { 10, 0 }, { 0, 0 }, { 5, 5 } } };
  const auto offsets = lkapp::placeLabels(labels, narrow, {});
  ASSERT_EQ(offsets.size(), 3u);
  EXPECT_EQ(offsets[0], offsets[1]);
  // No text: its offset as given, and in no one's way.
  EXPECT_DOUBLE_EQ(offsets[2][0], 5.0);
  EXPECT_DOUBLE_EQ(offsets[2][1], 5.0);
}

TEST(LabelPlacement, ALabelKeepsOutOfThePartsGiven)
{
  // The orientation cube at the window's top right: a name of a point below
  // it stands clear of it, a line lower, on the point's other side, or ...
  const lkapp::LabelRoom cube{ 870.0, 638.0, 996.0, 746.0 };
  const lkapp::Label label = name(600, 630);
  const auto free = lkapp::placeLabels({ label }, Window);
  ASSERT_TRUE(overlap({ 620, 650, 920, 668 }, { cube[0], cube[1], cube[2], cube[3] })); // its place without the cube
  EXPECT_DOUBLE_EQ(free[0][0], 20.0);
  const auto offsets = lkapp::placeLabels({ label }, Window, { cube });
  const auto boxes = boxesOf({ label }, offsets);
  EXPECT_FALSE(overlap(boxes[0], { cube[0], cube[1], cube[2], cube[3] }));
  EXPECT_DOUBLE_EQ(offsets[0][0], -320.0); // the other side, at the same height
  EXPECT_DOUBLE_EQ(offsets[0][1], 20.0);
}
