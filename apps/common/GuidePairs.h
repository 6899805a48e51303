#pragma once
/// \file GuidePairs.h
/// Which saw lines' cutting guides are joined into one resection guide: the
/// lines that bound one piece of the cut (the segment a resection takes out
/// lies between its two saw cuts), each with the next along the bone,
/// whatever order they were drawn in.
/// Shared by the planner (j) and latticekit-cut --join-guides.

#include <vtkPolyData.h>

class vtkLKGuideBarFilter;

#include <array>
#include <cstddef>
#include <functional>
#include <set>
#include <string>
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

/// The lines joined into one part each: chains of lines, each in its order
/// along the bone, where each line and the next bound one piece of the cut
/// (the segment between them). A line is joined on each of its sides at most
/// once (to one other line of the piece there), and no chain closes on
/// itself (a ring of bone cut all round): so a bone cut across several times
/// gives one chain of all its lines, in their order along it, whatever order
/// they were drawn in. A piece bounded by more than two lines (a ramus with
/// its condyle and coronoid cut off) joins two of them, in stroke order
/// (those on the fewest pieces first); without a cut (one piece, the whole
/// bone) lines join in pairs in stroke order (1 with 2, 3 with 4). Each
/// chain starts at its end with the smaller index; chains are in the order of
/// their smallest lines, and lines joined to none are in none.
std::vector<std::vector<std::size_t>> chainLinesByPiece(const std::vector<std::set<std::size_t>>& piecesOfLine);

/// A run of lines joined into one part, or why it could not be (`error`
/// empty when it was).
struct JoinedRun
{
  std::vector<std::size_t> lines; ///< in their order along the bone
  std::string error;
};

/// Joins a chain of lines (chainLinesByPiece), or as much of it as can be:
/// `join(lines)` makes the part of `lines` and says why it could not (empty
/// when it did). Lines that are not `usable` (no guide was made for them)
/// split the chain, and are in no run. When a run cannot be joined whole,
/// each line and the next are tried alone, and the run is split where they
/// cannot be (two guides too far apart, facing apart): those two are a
/// failed run with its reason, and the runs either side are joined on their
/// own. Should a run whose every two neighbours can be joined still fail
/// whole (no one direction puts all its guides on the bone), it is given
/// with its reason, and then split into runs from its start, each as long
/// as can be joined. The runs are in the chain's order.
std::vector<JoinedRun> joinChain(const std::vector<std::size_t>& chain,
  const std::function<bool(std::size_t)>& usable,
  const std::function<std::string(const std::vector<std::size_t>&)>& join);

/// The other lines that share a piece with line `line` (its neighbours, in
/// order): for a line left out of every pair, empty when no other line bounds
/// a piece with it, else the lines beside it (each paired with another).
std::vector<std::size_t> lineNeighbours(std::size_t line, const std::vector<std::set<std::size_t>>& piecesOfLine);

/// Why line `line` stays apart, in words, or empty when it is in one of
/// `chains` (it is joined): "no other
/// saw line bounds a piece of the cut with it (...)", "the saw line beside it
/// (stroke 3) is joined to another there" or "the saw lines beside it
/// (strokes 1, 2 and 3) are joined to others there", with `lineWord` ("saw
/// line") and `numberWord` ("stroke") as the caller names them, and `number`
/// giving a line's number as the user knows it.
std::string whyLineStaysApart(std::size_t line, const std::vector<std::set<std::size_t>>& piecesOfLine,
  const std::vector<std::vector<std::size_t>>& chains, const std::string& lineWord, const std::string& numberWord,
  const std::function<std::string(std::size_t)>& number);

/// Less than this (mm) inside another part is touching it, not overlapping.
constexpr double guidesOverlapTolerance = 0.05;

/// How far two closed parts overlap along the bone (mm: the spread, along
/// the mean of their saw planes' normals (GuidePlaneNormal; else from one's
/// centre to the other's), of the points of either inside the other by more
/// than guidesOverlapTolerance), 0 where no point is: two cutting guides on
/// saw lines nearer than their reaches, which cannot be on the bone
/// together. Moving a saw line about that much farther parts them.
double guidesOverlap(vtkPolyData* a, vtkPolyData* b);

/// Two of a plan's guides that overlap (guidesOverlap over
/// guidesOverlapTolerance), by their indices, first < second.
struct GuideOverlap
{
  std::size_t first = 0, second = 0;
  double along = 0.0; ///< mm along the bone
};

/// Every two of `guides` that overlap, in order (null or empty guides,
/// ones not made, are in none). The planner and latticekit-cut say each.
std::vector<GuideOverlap> overlappingGuides(const std::vector<vtkPolyData*>& guides);

/// How a resection guide's guides (those of `lines`, in its order) are
/// joined, in words: "joined by a bar of 4.0 mm, 22 mm long and 1.8 mm clear
/// of the bone between them", for more "joined by 2 bars of 4.0 mm, 22 and
/// 30 mm long and at least 1.8 mm clear of the bone between them"; guides
/// that overlap "merged into one block (they overlap; every slot and screw
/// hole open through it)"; and both: "joined by a bar of ..., those of
/// strokes 1 and 4 merged into one block (...)"; guides apart in the chain
/// that overlap where their saw planes cross add "; the guides of strokes 1
/// and 3 overlap where their saw planes cross near the bone, each cut by the
/// other's slot and screw holes"; with `numberWord` ("stroke")
/// and `number` giving a line's number as the user knows it.
std::string joinText(vtkLKGuideBarFilter* bar, const std::vector<std::size_t>& lines, const std::string& numberWord,
  const std::function<std::string(std::size_t)>& number);

/// vtkLKGuideBarFilter's `error` as the apps say it, after "... are not
/// joined: ": without its opening "Cannot join the guides: ", and with its
/// guides, numbered by their place among its inputs ("guide 2", "guides 1
/// and 3"), named by the lines they are on: "guide of stroke 4", "guides of
/// strokes 4 and 3", for the guides of `lines` in that order.
std::string guidesByLine(const std::string& error, const std::vector<std::size_t>& lines, const std::string& numberWord,
  const std::function<std::string(std::size_t)>& number);

/// How a resection guide goes on, in words: "along (0.092, 0.983, -0.157),
/// its steepest contact 4.6 degrees short of square to that", or, with an
/// undercut, "..., its contact up to 8.3 degrees past square to that over
/// 6.4 mm^2 (an undercut: trim there if it binds)".
std::string insertionText(vtkLKGuideBarFilter* bar);

/// "1, 3 and 2": the lines of `chain` by `number`, in its order.
std::string chainNumbers(const std::vector<std::size_t>& chain, const std::function<std::string(std::size_t)>& number,
  const std::string& separator = ", ", const std::string& last = " and ");

} // namespace lkapp
