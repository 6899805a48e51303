#pragma once
/// \file LabelPlacement.h
/// Where the captions of a view stand: beside their points, inside the
/// room the view leaves them, and not over each other.

#include <array>
#include <vector>

namespace lkapp
{

/// A label to place, in display pixels: its point, the size its text takes,
/// and where its text's lower-left corner stands from the point when
/// nothing is in the way (`offset[0]` > 0: right of it, and as far left of
/// it on the other side).
struct Label
{
  std::array<double, 2> at{ 0.0, 0.0 };
  std::array<double, 2> size{ 0.0, 0.0 };
  std::array<double, 2> offset{ 0.0, 0.0 };
};

/// The part of the view the labels may take, or a part they must keep out
/// of: left, bottom, right, top.
using LabelRoom = std::array<double, 4>;

/// For each label, in order, the offset of its text's lower-left corner
/// from its point. A label stands right of its point as `offset` says, or
/// left of it where the right would pass the room's right edge, or, where
/// both sides would pass the room, as `offset` says moved into the room
/// (ending at its right edge, or starting at its left; at its left where it
/// is wider than the room). A label that would lie over one
/// placed before it or over one of `keepOut` (with `gap` pixels between
/// them) goes to the other side
/// of its point, then a line further from its point (up where `offset[1]`
/// >= 0), then a line nearer, then two lines, ... (a line being its height
/// and `gap`) within the room, at the first place free of them; it keeps
/// the first place where none is free within `steps` lines. Its height is
/// kept within the room where the room is high enough. A label of no size
/// (no text) keeps `offset` and is in no other's way.
std::vector<std::array<double, 2>> placeLabels(const std::vector<Label>& labels, const LabelRoom& room,
  const std::vector<LabelRoom>& keepOut = {}, double gap = 3.0, int steps = 12);

} // namespace lkapp
