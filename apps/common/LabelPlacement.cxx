#include "LabelPlacement.h"

#include <algorithm>

namespace lkapp
{

namespace
{

/// A label's text where it stands: its lower-left corner and its size.
struct Box
{
  double x, y, width, height;
};

bool apart(const Box& a, const Box& b, double gap)
{
  return a.x + a.width + gap <= b.x || b.x + b.width + gap <= a.x || a.y + a.height + gap <= b.y ||
    b.y + b.height + gap <= a.y;
}

} // namespace

std::vector<std::array<double, 2>> placeLabels(const std::vector<Label>& labels, const LabelRoom& room,
  const std::vector<LabelRoom>& keepOut, double gap, int steps)
{
  const double left = room[0], bottom = room[1], right = room[2], top = room[3];
  std::vector<Box> placed; // the parts kept out of, then the labels placed
  for (const LabelRoom& part : keepOut)
    placed.push_back({ part[0], part[1], part[2] - part[0], part[3] - part[1] });
  std::vector<std::array<double, 2>> offsets;
  placed.reserve(placed.size() + labels.size());
  offsets.reserve(labels.size());
  for (const Label& label : labels)
  {
    const double w = label.size[0], h = label.size[1];
    const double x = label.at[0], y = label.at[1];
    if (w <= 0.0 || h <= 0.0) // no text: nothing to place, nothing in the way
    {
      offsets.push_back(label.offset);
      continue;
    }
    // Its sides: as `offset` says and the other side of its point, those
    // within the room; where neither is, as `offset` says moved into it.
    std::vector<double> starts;
    const double asSaid = x + label.offset[0], mirrored = x - label.offset[0] - w;
    for (const double start : { asSaid, mirrored })
      if (start >= left && start + w <= right)
        starts.push_back(start);
    if (starts.empty())
      starts.push_back(std::max(left, std::min(asSaid, right - w)));
    // Its heights: as `offset` says (within the room where the room is high
    // enough), then a line further from its point, a line nearer, two ...
    double first = y + label.offset[1];
    if (top - bottom >= h)
      first = std::clamp(first, bottom, top - h);
    const double line = h + gap, away = label.offset[1] >= 0.0 ? 1.0 : -1.0;
    std::vector<double> heights{ first };
    for (int k = 1; k <= steps; ++k)
      for (const double sign : { away, -away })
        if (const double at = first + sign * k * line; at >= bottom && at + h <= top)
          heights.push_back(at);
    Box chosen{ starts.front(), first, w, h };
    bool free = false;
    for (std::size_t i = 0; i < heights.size() && !free; ++i)
      for (std::size_t j = 0; j < starts.size() && !free; ++j)
      {
        const Box box{ starts[j], heights[i], w, h };
        free = std::all_of(placed.begin(), placed.end(), [&](const Box& b) { return apart(box, b, gap); });
        if (free)
          chosen = box;
      }
    placed.push_back(chosen);
    offsets.push_back({ chosen.x - x, chosen.y - y });
  }
  return offsets;
}

} // namespace lkapp
