#pragma once
/// \file WrinklyNets.h
/// Example control meshes for wrinkly surfaces (seed 000, figures 12 and 13),
/// flat in the z = 0 plane, with deterministic pseudo-random heights and RGB
/// colours (attributeComponents 3) so that the examples are reproducible.
/// The outermost ring of points is virtual (the paper's figures do the same).
///
/// - regular net: a grid (the 2-direction net, figure 12 a);
/// - polygon net: a central cell with `sides` corners, a strip of quads
///   outside every side and a grid in the wedge at every corner. The strip
///   lines of side i turn, through the wedge, into the cross lines of side
///   i + 1, so the two groups alternate from side to side: with an even
///   number of sides 2N the axes fall into two groups and the U (and V) axes
///   run in N directions (N-direction net: 4 sides for N = 2, 6 for the
///   3-direction net of figure 13, 8 for the 4-direction net of figure 12 b).
///   An odd number of sides puts every axis in one group (a test of the
///   refusal);
/// - annular net: rings (cyclic axes) around a central polygon and spokes
///   (translation axes) ending at it; the points of the inner ring have three
///   links and three-sided patches (figures 11 b and 12 c).

#include "latticekit/WrinklyGlobalAxes.h"

namespace lk
{

struct WrinklyNetStyle
{
  double spacing = 1.0;        ///< distance between neighbouring points
  double heightAmplitude = 0.3; ///< heights are uniform in [-a, a]
  unsigned seed = 1;
};

/// cellsU x cellsV cells, (cellsU + 1) x (cellsV + 1) points, row-major
/// (point i + (cellsU + 1) j). Needs cellsU, cellsV >= 2.
WrinklyControlMesh wrinklyRegularNet(int cellsU, int cellsV, const WrinklyNetStyle& style = {});

/// sides >= 3, rings >= 1 (quads outwards), edgeCells >= 1 (quads along a
/// side; with more than one, the points inside a side of the central cell
/// have three links and three-sided patches).
WrinklyControlMesh wrinklyPolygonNet(int sides, int rings, int edgeCells, const WrinklyNetStyle& style = {});

/// spokes >= 3, rings >= 2.
WrinklyControlMesh wrinklyAnnularNet(int spokes, int rings, const WrinklyNetStyle& style = {});

} // namespace lk
