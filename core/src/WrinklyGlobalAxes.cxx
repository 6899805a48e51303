#include "latticekit/WrinklyGlobalAxes.h"

#include <cmath>
#include <deque>
#include <map>
#include <stdexcept>
#include <string>

namespace lk
{
namespace
{

[[noreturn]] void refuse(const std::string& why)
{
  throw std::invalid_argument(why);
}

/// A point's links in fan order, with the cell between slot s and s + 1.
struct Fan
{
  std::array<int, 4> slot{ { -1, -1, -1, -1 } };
  std::array<int, 4> gapCell{ { -1, -1, -1, -1 } };
};

double cornerAngle(const WrinklyControlMesh& m, int v, int a, int b)
{
  return angleAt(m.points[v], m.points[a], m.points[b]);
}

} // namespace

WrinklyGlobalAxes buildWrinklyGlobalAxes(const WrinklyControlMesh& m)
{
  const int np = static_cast<int>(m.points.size());
  if (np == 0 || m.faces.empty())
    refuse("the control mesh is empty");
  if (!m.heights.empty() && static_cast<int>(m.heights.size()) != np)
    refuse("there must be one height per control point");
  if (m.attributeComponents < 0 ||
    (m.attributeComponents > 0 && m.attributes.size() != static_cast<std::size_t>(np) * m.attributeComponents))
    refuse("the attributes must have attributeComponents values per control point");
  if (!m.isVirtual.empty() && static_cast<int>(m.isVirtual.size()) != np)
    refuse("isVirtual must have one flag per control point");
  for (const Vec3& p : m.points)
    if (!p.allFinite())
      refuse("a control point is not finite (NaN or infinite)");

  // Fan transitions around every point: link prev -> (link next, cell).
  std::vector<std::map<int, std::pair<int, int>>> step(np);
  for (int f = 0; f < static_cast<int>(m.faces.size()); ++f)
  {
    const auto& face = m.faces[f];
    const int k = static_cast<int>(face.size());
    if (k < 3)
      refuse("cell " + std::to_string(f) + " has fewer than three corners");
    for (int p = 0; p < k; ++p)
    {
      const int v = face[p], prev = face[(p + k - 1) % k], next = face[(p + 1) % k];
      if (v < 0 || v >= np || prev < 0 || prev >= np || next < 0 || next >= np)
        refuse("cell " + std::to_string(f) + " names a point that does not exist");
      if (v == prev || v == next || prev == next)
        refuse("cell " + std::to_string(f) + " repeats a point");
      if (!step[v].emplace(prev, std::make_pair(next, f)).second)
        refuse("the control mesh is not a consistently oriented manifold at point " + std::to_string(v));
    }
  }

  WrinklyGlobalAxes out;
  out.frames.resize(np);
  std::vector<Fan> fans(np);
  for (int v = 0; v < np; ++v)
  {
    if (step[v].empty())
      continue;
    // Interior iff the transitions form one cycle through every link.
    std::vector<int> links;
    std::vector<int> cells;
    bool interior = true;
    int link = step[v].begin()->first;
    for (std::size_t guard = 0; guard <= step[v].size(); ++guard)
    {
      auto it = step[v].find(link);
      if (it == step[v].end())
      {
        interior = false;
        break;
      }
      links.push_back(link);
      cells.push_back(it->second.second);
      link = it->second.first;
      if (link == links.front())
        break;
    }
    interior = interior && link == links.front() && links.size() == step[v].size();
    const bool isVirtual = m.isVirtual.empty() ? !interior : m.isVirtual[v] != 0;
    if (isVirtual)
      continue;
    if (!interior)
      refuse("real control point " + std::to_string(v) +
        " lies on the border of the control mesh; border points must be virtual (figure 11)");
    const int k = static_cast<int>(links.size());
    if (k > 4)
      refuse("control point " + std::to_string(v) + " has " + std::to_string(k) +
        " links; a wrinkly control point has at most four (+-u, +-v)");
    if (k < 2)
      refuse("control point " + std::to_string(v) + " has fewer than two links");
    Fan& fan = fans[v];
    if (k == 4)
    {
      for (int s = 0; s < 4; ++s)
      {
        fan.slot[s] = links[s];
        fan.gapCell[s] = cells[s];
      }
    }
    else if (k == 3)
    {
      int wide = 0;
      double best = -1.0;
      for (int s = 0; s < 3; ++s)
      {
        // Most corners first, then the widest corner angle.
        const double a = 10.0 * static_cast<double>(m.faces[cells[s]].size()) +
          cornerAngle(m, v, links[s], links[(s + 1) % 3]);
        if (a > best)
        {
          best = a;
          wide = s;
        }
      }
      const int a = links[wide], b = links[(wide + 1) % 3], c = links[(wide + 2) % 3];
      fan.slot = { { a, -1, b, c } };
      fan.gapCell = { { cells[wide], cells[wide], cells[(wide + 1) % 3], cells[(wide + 2) % 3] } };
    }
    else
    {
      const double angle = cornerAngle(m, v, links[0], links[1]);
      if (angle > 3.0 * M_PI / 4.0)
      {
        fan.slot = { { links[0], -1, links[1], -1 } };
        fan.gapCell = { { cells[0], cells[0], cells[1], cells[1] } };
      }
      else
      {
        fan.slot = { { links[0], links[1], -1, -1 } };
        fan.gapCell = { { cells[0], cells[1], cells[1], cells[1] } };
      }
    }
    out.frames[v].real = true;
    out.patchPoints.push_back(v);
  }
  if (out.patchPoints.empty())
    refuse("the control mesh has no real (interior) control point");

  auto slotOf = [&](int at, int neighbour) {
    for (int s = 0; s < 4; ++s)
      if (fans[at].slot[s] == neighbour)
        return s;
    return -1;
  };
  auto follow = [&](int at, int exitSlot, int& next, int& entrySlot) {
    next = fans[at].slot[exitSlot];
    if (next < 0 || !out.frames[next].real)
      return false;
    entrySlot = slotOf(next, at);
    return entrySlot >= 0;
  };

  // Chains of local axes (figure 7).
  struct Chain
  {
    std::vector<int> points;
    std::vector<int> plusSlot;
    bool cyclic = false;
  };
  std::vector<Chain> chains;
  std::vector<std::array<int, 2>> chainOf(np, { { -1, -1 } });
  std::vector<std::array<int, 2>> indexOn(np, { { -1, -1 } });
  std::vector<std::array<int, 2>> plusOf(np, { { -1, -1 } });
  for (int v : out.patchPoints)
  {
    for (int a = 0; a < 2; ++a)
    {
      if (chainOf[v][a] >= 0)
        continue;
      // Walk backwards (through slot a + 2) to the start.
      int cur = v, fwd = a, back = a + 2;
      bool cyclic = false;
      for (;;)
      {
        int y, sy;
        if (!follow(cur, back, y, sy))
          break;
        if (y == v && sy % 2 == a)
        {
          cyclic = true;
          cur = v;
          fwd = a;
          break;
        }
        cur = y;
        fwd = sy;
        back = (sy + 2) % 4;
      }
      Chain chain;
      chain.cyclic = cyclic;
      const int id = static_cast<int>(chains.size());
      const int start = cur, startAxis = fwd % 2;
      for (;;)
      {
        if (chainOf[cur][fwd % 2] >= 0)
          refuse("the axes through control point " + std::to_string(cur) + " could not be followed consistently");
        chainOf[cur][fwd % 2] = id;
        indexOn[cur][fwd % 2] = static_cast<int>(chain.points.size());
        plusOf[cur][fwd % 2] = fwd;
        chain.points.push_back(cur);
        chain.plusSlot.push_back(fwd);
        int y, sy;
        if (!follow(cur, fwd, y, sy))
          break;
        if (y == start && sy % 2 == startAxis)
          break;
        cur = y;
        fwd = (sy + 2) % 4;
      }
      chains.push_back(std::move(chain));
    }
  }

  // Two-grouping: the two local axes of a point are in different groups.
  std::vector<std::vector<std::pair<int, int>>> crossings(chains.size());
  for (int v : out.patchPoints)
  {
    const int c0 = chainOf[v][0], c1 = chainOf[v][1];
    if (c0 == c1)
      refuse("the global axes fall into one group (section 3.1): the axis through control point " +
        std::to_string(v) + " crosses itself there, so it would have to be both a U and a V axis; "
        "the 2D IST needs every axis in either the U or the V group");
    crossings[c0].emplace_back(c1, v);
    crossings[c1].emplace_back(c0, v);
  }
  std::vector<int> group(chains.size(), -1);
  for (int v : out.patchPoints)
  {
    const int seed = chainOf[v][0];
    if (group[seed] >= 0)
      continue;
    group[seed] = 0;
    std::deque<int> queue{ seed };
    while (!queue.empty())
    {
      const int c = queue.front();
      queue.pop_front();
      for (const auto& [d, at] : crossings[c])
      {
        if (group[d] < 0)
        {
          group[d] = 1 - group[c];
          queue.push_back(d);
        }
        else if (group[d] == group[c])
          refuse("the global axes fall into one group (section 3.1): following crossing axes from control "
                 "point " + std::to_string(v) + " around to control point " + std::to_string(at) +
            " makes its two axes parallel, so no axis can be told U from V; the 2D IST needs every axis "
            "in either the U or the V group");
      }
    }
  }

  // Frames and axes per group.
  std::vector<int> idInGroup(chains.size());
  for (std::size_t c = 0; c < chains.size(); ++c)
  {
    idInGroup[c] = static_cast<int>(out.axes[group[c]].size());
    WrinklyAxis axis;
    axis.points = chains[c].points;
    axis.cyclic = chains[c].cyclic;
    out.axes[group[c]].push_back(std::move(axis));
  }
  for (int v : out.patchPoints)
  {
    WrinklyFrame& fr = out.frames[v];
    int slotOfRole[4];
    for (int a = 0; a < 2; ++a)
    {
      const int g = group[chainOf[v][a]];
      fr.axis[g] = idInGroup[chainOf[v][a]];
      fr.index[g] = indexOn[v][a];
      const int plus = plusOf[v][a];
      slotOfRole[g == 0 ? PlusU : PlusV] = plus;
      slotOfRole[g == 0 ? MinusU : MinusV] = (plus + 2) % 4;
    }
    for (int r = 0; r < 4; ++r)
    {
      fr.link[r] = fans[v].slot[slotOfRole[r]];
      if (fr.link[r] < 0)
        fr.missingCell[r] = fans[v].gapCell[slotOfRole[r]];
    }
    auto cornerCell = [&](int ru, int rv) {
      const int su = slotOfRole[ru], sv = slotOfRole[rv];
      return (su + 1) % 4 == sv ? fans[v].gapCell[su] : fans[v].gapCell[sv];
    };
    fr.corner[0] = cornerCell(MinusU, MinusV);
    fr.corner[1] = cornerCell(PlusU, MinusV);
    fr.corner[2] = cornerCell(MinusU, PlusV);
    fr.corner[3] = cornerCell(PlusU, PlusV);
  }
  // Eq. 8: along each axis, does the crossing group's + side flip?
  for (int g = 0; g < 2; ++g)
  {
    for (WrinklyAxis& axis : out.axes[g])
    {
      axis.crossFlip.assign(axis.points.size(), 0);
      for (std::size_t k = 0; k + 1 < axis.points.size(); ++k)
      {
        const WrinklyFrame& a = out.frames[axis.points[k]];
        const WrinklyFrame& b = out.frames[axis.points[k + 1]];
        // Corners beside the shared link: for U axes (+u, +v) of a against
        // (-u, +v) of b; for V axes (+u, +v) of a against (+u, -v) of b.
        // In both cases the opposite side is b's (-u, -v) corner.
        const int aSide = a.corner[3];
        const int bSame = g == 0 ? b.corner[2] : b.corner[1];
        const bool flipped = aSide != bSame && aSide == b.corner[0];
        axis.crossFlip[k + 1] = static_cast<char>(axis.crossFlip[k] ^ (flipped ? 1 : 0));
      }
    }
  }
  return out;
}

double parallelParameter(const WrinklyGlobalAxes& axes, int group, int from, int to, double value)
{
  const int other = 1 - group;
  const int n = static_cast<int>(axes.frames.size());
  if (group < 0 || group > 1 || from < 0 || to < 0 || from >= n || to >= n || !axes.frames[from].real ||
    !axes.frames[to].real || axes.frames[from].axis[other] != axes.frames[to].axis[other])
    throw std::invalid_argument("parallelParameter: the two points must be real and share an axis of the other group");
  const WrinklyAxis& along = axes.axes[other][axes.frames[from].axis[other]];
  const double frac = value - axes.frames[from].index[group];
  const double onChain = along.crossFlip[axes.frames[from].index[other]] ? 1.0 - frac : frac;
  const double local = along.crossFlip[axes.frames[to].index[other]] ? 1.0 - onChain : onChain;
  return axes.frames[to].index[group] + local;
}

} // namespace lk
