#include "common/GuidePairs.h"
#include "common/AppSupport.h"

#include "vtkLKGuideBarFilter.h"

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkImplicitPolyDataDistance.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkStaticPointLocator.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <regex>
#include <tuple>

namespace lkapp
{

std::vector<std::set<std::size_t>> piecesAlongLines(const std::vector<vtkPolyData*>& pieces,
  const std::vector<std::vector<std::array<double, 3>>>& lines, double tolerance)
{
  std::vector<std::set<std::size_t>> along(lines.size());
  const double tolerance2 = tolerance * tolerance;
  for (std::size_t p = 0; p < pieces.size(); ++p)
  {
    if (!pieces[p] || pieces[p]->GetNumberOfPoints() == 0)
      continue;
    vtkNew<vtkStaticPointLocator> locator;
    locator->SetDataSet(pieces[p]);
    locator->BuildLocator();
    for (std::size_t l = 0; l < lines.size(); ++l)
    {
      std::size_t on = 0;
      for (const auto& x : lines[l])
      {
        double d2 = 0.0;
        if (locator->FindClosestPointWithinRadius(tolerance, x.data(), d2) >= 0 && d2 <= tolerance2)
          ++on;
      }
      if (!lines[l].empty() && 2 * on >= lines[l].size())
        along[l].insert(p);
    }
  }
  return along;
}

std::vector<std::size_t> lineNeighbours(std::size_t line, const std::vector<std::set<std::size_t>>& piecesOfLine)
{
  std::vector<std::size_t> neighbours;
  for (std::size_t other = 0; other < piecesOfLine.size(); ++other)
  {
    if (other == line)
      continue;
    const auto& a = piecesOfLine[line];
    const auto& b = piecesOfLine[other];
    if (std::any_of(a.begin(), a.end(), [&](std::size_t p) { return b.count(p) > 0; }))
      neighbours.push_back(other);
  }
  return neighbours;
}

std::vector<std::vector<std::size_t>> chainLinesByPiece(const std::vector<std::set<std::size_t>>& piecesOfLine)
{
  const std::size_t n = piecesOfLine.size();
  // The lines on each piece, in order.
  std::map<std::size_t, std::vector<std::size_t>> linesOn;
  for (std::size_t l = 0; l < n; ++l)
    for (std::size_t p : piecesOfLine[l])
      linesOn[p].push_back(l);
  // Pieces with fewer lines first (a piece between two lines joins them
  // whatever else), then in order.
  std::vector<std::size_t> order;
  for (const auto& [p, lines] : linesOn)
    if (lines.size() >= 2)
      order.push_back(p);
  std::stable_sort(order.begin(), order.end(),
    [&](std::size_t a, std::size_t b) { return linesOn[a].size() < linesOn[b].size(); });
  // The joins: each line's side (a piece it is on) used once, each line
  // joined twice at most, no ring (union-find on the chains so far).
  std::vector<std::size_t> root(n);
  std::iota(root.begin(), root.end(), 0);
  std::function<std::size_t(std::size_t)> find = [&](std::size_t l) {
    return root[l] == l ? l : root[l] = find(root[l]);
  };
  std::vector<std::vector<std::size_t>> joined(n);
  for (std::size_t p : order)
  {
    std::vector<std::size_t> lines = linesOn[p];
    // Lines on one piece only (an end of the chain there) before those on two.
    std::stable_sort(lines.begin(), lines.end(),
      [&](std::size_t a, std::size_t b) { return piecesOfLine[a].size() < piecesOfLine[b].size(); });
    std::vector<bool> used(lines.size(), false);
    for (std::size_t i = 0; i < lines.size(); ++i)
    {
      if (used[i] || joined[lines[i]].size() >= 2)
        continue;
      for (std::size_t k = i + 1; k < lines.size(); ++k)
      {
        const std::size_t a = lines[i], b = lines[k];
        if (used[k] || joined[b].size() >= 2 || find(a) == find(b))
          continue;
        joined[a].push_back(b);
        joined[b].push_back(a);
        root[find(a)] = find(b);
        used[i] = used[k] = true;
        break;
      }
    }
  }
  // Each chain from its end with the smaller index.
  std::vector<std::vector<std::size_t>> chains;
  std::vector<bool> placed(n, false);
  for (std::size_t l = 0; l < n; ++l)
  {
    if (placed[l] || joined[l].size() != 1)
      continue;
    std::vector<std::size_t> chain{ l };
    placed[l] = true;
    for (std::size_t at = l;;)
    {
      const auto next =
        std::find_if(joined[at].begin(), joined[at].end(), [&](std::size_t m) { return !placed[m]; });
      if (next == joined[at].end())
        break;
      at = *next;
      placed[at] = true;
      chain.push_back(at);
    }
    chains.push_back(chain);
  }
  std::sort(chains.begin(), chains.end(), [](const auto& a, const auto& b) {
    return *std::min_element(a.begin(), a.end()) < *std::min_element(b.begin(), b.end());
  });
  return chains;
}

std::vector<JoinedRun> joinChain(const std::vector<std::size_t>& chain,
  const std::function<bool(std::size_t)>& usable,
  const std::function<std::string(const std::vector<std::size_t>&)>& join)
{
  std::vector<JoinedRun> runs;
  // Split at the lines without a guide.
  std::vector<std::vector<std::size_t>> pieces(1);
  for (std::size_t line : chain)
    if (usable(line))
      pieces.back().push_back(line);
    else if (!pieces.back().empty())
      pieces.emplace_back();
  for (const auto& run : pieces)
  {
    if (run.size() < 2)
      continue;
    std::string why = join(run);
    if (why.empty() || run.size() == 2)
    {
      runs.push_back({ run, why });
      continue;
    }
    // Each line with the next, alone; the run split where they fail.
    std::vector<std::size_t> part{ run[0] };
    auto finish = [&]() {
      if (part.size() == 2)
        runs.push_back({ part, std::string() }); // made above, alone
      else if (part.size() > 2)
      {
        const std::string whole = part == run ? why : join(part);
        runs.push_back({ part, whole });
        // Whole it cannot be (no one direction puts it all on): runs from
        // its start, each as long as can be joined.
        for (std::size_t first = 0; !whole.empty() && first + 1 < part.size();)
        {
          std::size_t last = first + 1; // two neighbours join
          while (last + 1 < part.size() &&
            join(std::vector<std::size_t>(part.begin() + first, part.begin() + last + 2)).empty())
            ++last;
          runs.push_back({ std::vector<std::size_t>(part.begin() + first, part.begin() + last + 1), std::string() });
          first = last + 1;
        }
      }
    };
    for (std::size_t k = 0; k + 1 < run.size(); ++k)
    {
      const std::string pair = join({ run[k], run[k + 1] });
      if (pair.empty())
      {
        part.push_back(run[k + 1]);
        continue;
      }
      finish();
      runs.push_back({ { run[k], run[k + 1] }, pair });
      part = { run[k + 1] };
    }
    finish();
  }
  return runs;
}

double guidesOverlap(vtkPolyData* a, vtkPolyData* b)
{
  if (!a || !b || a->GetNumberOfPolys() == 0 || b->GetNumberOfPolys() == 0)
    return 0.0;
  double boxA[6], boxB[6];
  a->GetBounds(boxA);
  b->GetBounds(boxB);
  for (int k = 0; k < 3; ++k)
    if (boxA[2 * k + 1] < boxB[2 * k] || boxB[2 * k + 1] < boxA[2 * k])
      return 0.0;
  // The direction along the bone: the guides' saw planes' mean normal
  // (their field data), else from one part's centre to the other's.
  std::array<double, 3> axis{ 0.0, 0.0, 0.0 };
  for (vtkPolyData* part : { a, b })
  {
    vtkDataArray* n = part->GetFieldData() ? part->GetFieldData()->GetArray("GuidePlaneNormal") : nullptr;
    if (!n || n->GetNumberOfComponents() != 3 || n->GetNumberOfTuples() < 1)
      continue;
    std::array<double, 3> normal;
    n->GetTuple(0, normal.data());
    if (!(vtkMath::Normalize(normal.data()) > 0.0))
      continue;
    const double sign = vtkMath::Dot(axis.data(), normal.data()) < 0.0 ? -1.0 : 1.0;
    for (int k = 0; k < 3; ++k)
      axis[k] += sign * normal[k];
  }
  if (!(vtkMath::Normalize(axis.data()) > 0.0))
  {
    double from[3], to[3];
    a->GetCenter(from);
    b->GetCenter(to);
    vtkMath::Subtract(to, from, axis.data());
    if (!(vtkMath::Normalize(axis.data()) > 0.0))
      axis = { 1.0, 0.0, 0.0 };
  }
  // The points of each inside the other (by more than a touch), and how far
  // they spread along that direction.
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (const auto& [part, other, box] : { std::make_tuple(a, b, boxB), std::make_tuple(b, a, boxA) })
  {
    vtkNew<vtkImplicitPolyDataDistance> inside; // negative inside: the parts face outward
    inside->SetInput(other);
    for (vtkIdType i = 0; i < part->GetNumberOfPoints(); ++i)
    {
      double x[3];
      part->GetPoint(i, x);
      if (x[0] < box[0] || x[0] > box[1] || x[1] < box[2] || x[1] > box[3] || x[2] < box[4] || x[2] > box[5])
        continue;
      if (inside->EvaluateFunction(x) < -guidesOverlapTolerance)
      {
        const double along = vtkMath::Dot(x, axis.data());
        low = std::min(low, along);
        high = std::max(high, along);
      }
    }
  }
  return high >= low ? high - low : 0.0;
}

std::vector<GuideOverlap> overlappingGuides(const std::vector<vtkPolyData*>& guides)
{
  std::vector<GuideOverlap> overlaps;
  for (std::size_t i = 0; i < guides.size(); ++i)
    for (std::size_t k = i + 1; k < guides.size(); ++k)
      if (const double along = guidesOverlap(guides[i], guides[k]); along > guidesOverlapTolerance)
        overlaps.push_back({ i, k, along });
  return overlaps;
}

namespace
{
std::string barsAndBlocks(vtkLKGuideBarFilter* bar, const std::vector<std::size_t>& lines,
  const std::string& numberWord, const std::function<std::string(std::size_t)>& number)
{
  const int bars = bar->GetNumberOfBars();
  std::string text;
  if (bars > 0)
  {
    std::string lengths;
    for (int b = 0; b < bars; ++b)
    {
      char length[32];
      std::snprintf(length, sizeof length, "%.0f", bar->GetBarLength(b));
      lengths += (b == 0 ? "" : b + 1 == bars ? " and " : ", ") + std::string(length);
    }
    char said[300];
    std::snprintf(said, sizeof said, "joined by %s of %.1f mm, %s mm long and %s%.1f mm clear of the bone between them",
      bars == 1 ? "a bar" : (std::to_string(bars) + " bars").c_str(), bar->GetBarDiameter(), lengths.c_str(),
      bars == 1 ? "" : "at least ", bar->GetBarGap());
    text = said;
  }
  if (bar->GetNumberOfMerges() == 0)
    return text;
  // The runs of guides merged into one block, by their lines.
  std::vector<std::vector<std::size_t>> blocks;
  for (std::size_t i = 0; i + 1 < lines.size(); ++i)
    if (bar->GetMerged(static_cast<int>(i)))
    {
      if (blocks.empty() || blocks.back().back() != lines[i])
        blocks.push_back({ lines[i] });
      blocks.back().push_back(lines[i + 1]);
    }
  const std::string slots = " (they overlap; every slot and screw hole open through it)";
  if (bars == 0 && blocks.size() == 1)
    return "merged into one block" + slots;
  std::string merged;
  for (std::size_t b = 0; b < blocks.size(); ++b)
    merged += (b == 0 ? "" : b + 1 == blocks.size() ? " and " : ", ") + chainNumbers(blocks[b], number);
  return text + (text.empty() ? "" : ", ") + "those of " + numberWord + "s " + merged +
    (blocks.size() == 1 ? " merged into one block" : " merged into a block each") + slots;
}
} // namespace

std::string joinText(vtkLKGuideBarFilter* bar, const std::vector<std::size_t>& lines, const std::string& numberWord,
  const std::function<std::string(std::size_t)>& number)
{
  const std::string text = barsAndBlocks(bar, lines, numberWord, number);
  if (bar->GetNumberOfCrossings() == 0)
    return text;
  // Guides apart in the chain that overlap where their saw planes cross.
  std::vector<std::string> pairs;
  for (std::size_t i = 0; i < lines.size(); ++i)
    for (std::size_t j = i + 2; j < lines.size(); ++j)
      if (bar->GetCrossed(static_cast<int>(i), static_cast<int>(j)))
        pairs.push_back(number(lines[i]) + " and " + number(lines[j]));
  std::string crossed;
  for (std::size_t p = 0; p < pairs.size(); ++p)
    crossed += (p == 0 ? "" : "; ") + pairs[p];
  return text + (text.empty() ? "" : "; ") + "the guides of " + numberWord + "s " + crossed +
    " overlap where their saw planes cross near the bone, each cut by the other's slot and screw holes";
}

std::string guidesByLine(const std::string& error, const std::vector<std::size_t>& lines, const std::string& numberWord,
  const std::function<std::string(std::size_t)>& number)
{
  static const std::regex guides("\\bguide(s?) ([0-9]+)( and ([0-9]+))?");
  auto line = [&](const std::string& k) {
    const std::size_t at = static_cast<std::size_t>(std::stoul(k));
    return at >= 1 && at <= lines.size() ? number(lines[at - 1]) : "?";
  };
  // The filter's opening words: the apps say "... are not joined: " first.
  static const std::string opening = "Cannot join the guides: ";
  const std::string said = error.rfind(opening, 0) == 0 ? error.substr(opening.size()) : error;
  std::string text;
  auto from = said.cbegin();
  for (std::sregex_iterator it(said.begin(), said.end(), guides), end; it != end; ++it)
  {
    const std::smatch& m = *it;
    text.append(from, m[0].first);
    if (m[1].length() > 0 && m[4].matched)
      text += "guides of " + numberWord + "s " + line(m[2].str()) + " and " + line(m[4].str());
    else if (m[1].length() == 0)
      text += "guide of " + numberWord + " " + line(m[2].str()) + m[3].str();
    else
      text += m[0].str();
    from = m[0].second;
  }
  text.append(from, said.cend());
  return text;
}

std::string insertionText(vtkLKGuideBarFilter* bar)
{
  const std::array<double, 3> toward = guideDirection(bar->GetApproachUsed()); // as the guides' "along"
  char text[300];
  if (bar->GetInsertionMargin() >= 0.0)
    std::snprintf(text, sizeof text, "along (%.3f, %.3f, %.3f), its steepest contact %.1f degrees short of square to that",
      toward[0], toward[1], toward[2], bar->GetInsertionMargin());
  else
    std::snprintf(text, sizeof text,
      "along (%.3f, %.3f, %.3f), its contact up to %.1f degrees past square to that over %.1f mm^2 (an undercut: "
      "trim there if it binds)",
      toward[0], toward[1], toward[2], -bar->GetInsertionMargin(), bar->GetUndercutArea());
  return text;
}

std::string chainNumbers(const std::vector<std::size_t>& chain, const std::function<std::string(std::size_t)>& number,
  const std::string& separator, const std::string& last)
{
  std::string text;
  for (std::size_t k = 0; k < chain.size(); ++k)
    text += (k == 0 ? "" : k + 1 == chain.size() ? last : separator) + number(chain[k]);
  return text;
}

std::string whyLineStaysApart(std::size_t line, const std::vector<std::set<std::size_t>>& piecesOfLine,
  const std::vector<std::vector<std::size_t>>& chains, const std::string& lineWord, const std::string& numberWord,
  const std::function<std::string(std::size_t)>& number)
{
  for (const std::vector<std::size_t>& chain : chains)
    if (std::find(chain.begin(), chain.end(), line) != chain.end())
      return {};
  const std::vector<std::size_t> beside = lineNeighbours(line, piecesOfLine);
  if (beside.empty())
    return "no other " + lineWord + " bounds a piece of the cut with it (a resection guide joins the " + lineWord +
      "s either side of one piece)";
  // A line beside it in no chain would have been joined to it.
  if (beside.size() == 1)
    return "the " + lineWord + " beside it (" + numberWord + " " + number(beside[0]) +
      ") is joined to another there";
  return "the " + lineWord + "s beside it (" + numberWord + "s " + chainNumbers(beside, number) +
    ") are joined to others there";
}

} // namespace lkapp
