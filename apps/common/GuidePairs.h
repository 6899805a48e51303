#pragma once
/// \file GuidePairs.h
/// Which saw lines' cutting guides are joined into one resection guide: the
/// two lines that bound one piece of the cut (the segment a resection takes
/// out lies between its two saw cuts), whatever order they were drawn in.
/// Shared by the planner (j) and latticekit-cut --join-guides.

#include <vtkPolyData.h>

#include <array>
#include <cstddef>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace lkapp
{

/// The pieces each line runs along: piece p is in result[l] when at least
/// half of line l's points lie on points of piece p (within `tolerance`; the
/// cut gives each piece its own copy of a cut line's points). A line the cut
/// went along is on the two pieces either side of it; without a cut (one
/// piece, the whole bone) every line is on that piece.
std::vector<std::set<std::size_t>> piecesAlongLines(const std::vector<vtkPolyData*>& pieces,
  const std::vector<std::vector<std::array<double, 3>>>& lines, double tolerance);

/// The lines' pairs: two lines are paired when they are both on one piece,
/// and each line is in one pair at most. A maximum matching on a chain of
/// pieces (a bone cut across several times): the line with the fewest
/// unpaired neighbours goes first (the first such line in order on a tie),
/// with its first unpaired neighbour, so lines drawn in order along the bone
/// pair as drawn (1 with 2, 3 with 4) and lines drawn out of order pair as
/// they lie. Each pair has its smaller index first, and the pairs are in the
/// order of their first lines.
std::vector<std::pair<std::size_t, std::size_t>> pairLinesByPiece(
  const std::vector<std::set<std::size_t>>& piecesOfLine);

/// The other lines that share a piece with line `line` (its neighbours, in
/// order): for a line left out of every pair, empty when no other line bounds
/// a piece with it, else the lines beside it (each paired with another).
std::vector<std::size_t> lineNeighbours(std::size_t line, const std::vector<std::set<std::size_t>>& piecesOfLine);

} // namespace lkapp
