#pragma once
/// \file GuidePairs.h
/// Which saw lines' cutting guides are joined into one resection guide: the
/// two lines that bound one piece of the cut (the segment a resection takes
/// out lies between its two saw cuts), whatever order they were drawn in.
/// Shared by the planner (j) and latticekit-cut --join-guides.

#include <vtkPolyData.h>

#include <array>
#include <cstddef>
#include <functional>
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

/// Why line `line`, in none of `pairs`, stays apart, in words: "no other
/// saw line bounds a piece of the cut with it (...)", "the saw line beside it
/// (stroke 3) is joined to stroke 1" or "the saw lines beside it (strokes 1
/// and 3) are joined to others", with `lineWord` ("saw line") and
/// `numberWord` ("stroke") as the caller names them, and `number` giving a
/// line's number as the user knows it.
std::string whyLineStaysApart(std::size_t line, const std::vector<std::set<std::size_t>>& piecesOfLine,
  const std::vector<std::pair<std::size_t, std::size_t>>& pairs, const std::string& lineWord,
  const std::string& numberWord, const std::function<std::string(std::size_t)>& number);

} // namespace lkapp
