#pragma once
/// \file WrinklyGlobalAxes.h
/// Control meshes of wrinkly surfaces and their global axes (seed 000,
/// Fujimoto and Ohno, sections 3.1 and 3.2, figure 7, eq. 8).
///
/// A control mesh is a polygon mesh (cells of any size: the grid regions of
/// the paper) whose vertices are wrinkly control points. Vertices flagged
/// virtual (by default: the boundary vertices, as the outermost ring of the
/// paper's figures 12 and 13) carry positions and attributes for their
/// neighbours' patches but get no patch of their own (figure 11). Every real
/// control point must be interior and have 2 to 4 links (mesh edges), which
/// become its local axes:
///   - 4 links: opposite links in the cyclic order pair up (+-a, +-b);
///   - 3 links: the cell with the most corners (ties: the widest corner
///     angle) holds the missing link (figure 11 b: the centre polygon of an
///     annular net), the two links around that
///     cell are one axis, the third link is half of the other (figure 10 b);
///   - 2 links: more than 135 degrees apart they are one axis and the other
///     axis has no links at all; otherwise each is half of its own axis
///     (figure 10 c, d).
/// Global axes (figure 7) chain local axes through links: an axis leaving a
/// point by one link enters the neighbour's local axis that holds the link
/// back, and leaves by that axis' other link. A chain ends at a missing link
/// or a virtual point (translation axis) or returns to its start (cyclic
/// axis). Two-grouping (3.1): the two local axes of a point cross, so they
/// must fall in different groups; axes are coloured by breadth-first search
/// over these crossings. An axis that crosses itself, or an odd cycle of
/// crossings, puts every axis in one group: the mesh is refused, naming a
/// point where the conflict shows.
/// Orientation: each axis runs from its first point; a point's +u (+v) is the
/// link to the next point on its U (V) axis, and point k of an axis owns the
/// base interval [k, k + 1) (figure 6: local u in [0, 1] is global U - k).
/// Eq. 8 (G_PAR): points next to each other on a U axis have parallel V axes,
/// whose directions agree or are opposite; the flags that record this let a
/// V value be carried along the U axis (parallelParameter).

#include "latticekit/TriangleMesh.h"

#include <array>
#include <vector>

namespace lk
{

struct WrinklyControlMesh
{
  std::vector<Vec3> points;
  std::vector<std::vector<int>> faces; ///< polygons (grid regions)
  std::vector<double> heights;         ///< per point; empty: all 0
  int attributeComponents = 0;         ///< e.g. 3 for RGB, 4 for RGB + opacity
  std::vector<double> attributes;      ///< points x attributeComponents
  std::vector<char> isVirtual;         ///< per point; empty: boundary points are virtual
};

/// Roles of a point's four link slots.
enum WrinklyRole
{
  PlusU = 0,
  MinusU = 1,
  PlusV = 2,
  MinusV = 3
};

struct WrinklyFrame
{
  bool real = false;
  std::array<int, 4> link{ { -1, -1, -1, -1 } }; ///< neighbour per role, -1 missing
  /// Cell holding each corner: [0] (-u, -v), [1] (+u, -v), [2] (-u, +v), [3] (+u, +v).
  std::array<int, 4> corner{ { -1, -1, -1, -1 } };
  /// Cell holding each missing link's direction (-1 where the link exists).
  std::array<int, 4> missingCell{ { -1, -1, -1, -1 } };
  std::array<int, 2> axis{ { -1, -1 } };  ///< global U axis, global V axis
  std::array<int, 2> index{ { -1, -1 } }; ///< position on each
};

struct WrinklyAxis
{
  std::vector<int> points; ///< in order
  bool cyclic = false;
  /// Per position: is the crossing group's + direction opposite to the one
  /// at position 0 (eq. 8)?
  std::vector<char> crossFlip;
};

struct WrinklyGlobalAxes
{
  std::vector<WrinklyFrame> frames;       ///< per control point
  std::array<std::vector<WrinklyAxis>, 2> axes; ///< [0] U group, [1] V group
  std::vector<int> patchPoints;           ///< the real control points
};

/// Builds the frames and axes; throws std::invalid_argument with the reason
/// (bad indices, a real point on the border, more than four or fewer than
/// two links, axes in one group).
WrinklyGlobalAxes buildWrinklyGlobalAxes(const WrinklyControlMesh& mesh);

/// Eq. 8: a global parameter value on the `group` axis through `from` (in
/// from's base interval) to the parallel axis through `to`; `from` and `to`
/// must lie on one axis of the other group. Throws std::invalid_argument if
/// they do not.
double parallelParameter(const WrinklyGlobalAxes& axes, int group, int from, int to, double value);

} // namespace lk
