#include "common/GuidePairs.h"

#include <vtkNew.h>
#include <vtkStaticPointLocator.h>

#include <algorithm>

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

std::vector<std::pair<std::size_t, std::size_t>> pairLinesByPiece(
  const std::vector<std::set<std::size_t>>& piecesOfLine)
{
  const std::size_t n = piecesOfLine.size();
  std::vector<std::vector<std::size_t>> neighbours(n);
  for (std::size_t l = 0; l < n; ++l)
    neighbours[l] = lineNeighbours(l, piecesOfLine);
  std::vector<bool> paired(n, false);
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (;;)
  {
    // The unpaired line with the fewest unpaired neighbours (at least one).
    std::size_t best = n, bestCount = n + 1;
    for (std::size_t l = 0; l < n; ++l)
    {
      if (paired[l])
        continue;
      const auto count = static_cast<std::size_t>(std::count_if(
        neighbours[l].begin(), neighbours[l].end(), [&](std::size_t m) { return !paired[m]; }));
      if (count > 0 && count < bestCount)
      {
        best = l;
        bestCount = count;
      }
    }
    if (best == n)
      break;
    const std::size_t with =
      *std::find_if(neighbours[best].begin(), neighbours[best].end(), [&](std::size_t m) { return !paired[m]; });
    paired[best] = paired[with] = true;
    pairs.emplace_back(std::min(best, with), std::max(best, with));
  }
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

std::string whyLineStaysApart(std::size_t line, const std::vector<std::set<std::size_t>>& piecesOfLine,
  const std::vector<std::pair<std::size_t, std::size_t>>& pairs, const std::string& lineWord,
  const std::string& numberWord, const std::function<std::string(std::size_t)>& number)
{
  const std::vector<std::size_t> beside = lineNeighbours(line, piecesOfLine);
  if (beside.empty())
    return "no other " + lineWord + " bounds a piece of the cut with it (a resection guide joins the " + lineWord +
      "s either side of one piece)";
  if (beside.size() == 1)
  {
    const auto pair = std::find_if(pairs.begin(), pairs.end(),
      [&](const auto& q) { return q.first == beside[0] || q.second == beside[0]; });
    if (pair != pairs.end())
      return "the " + lineWord + " beside it (" + numberWord + " " + number(beside[0]) + ") is joined to " +
        numberWord + " " + number(pair->first == beside[0] ? pair->second : pair->first);
  }
  std::string why = "the " + lineWord + "s beside it (" + numberWord + "s ";
  for (std::size_t k = 0; k < beside.size(); ++k)
    why += (k == 0 ? "" : k + 1 == beside.size() ? " and " : ", ") + number(beside[k]);
  return why + ") are joined to others";
}

} // namespace lkapp
