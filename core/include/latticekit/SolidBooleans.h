#pragma once
/// \file SolidBooleans.h
/// The union of solids given by their closed surfaces: one surface round
/// all of them, where they overlap none of their faces inside the others.
/// A printed part made of several overlapping pieces (a resection guide's
/// two blocks and the bar between them) is one closed, outward-facing mesh
/// to a slicer and has the volume it looks to have.

#include "latticekit/TriangleMesh.h"

#include <string>
#include <vector>

namespace lk
{

/// The union of `solids` (CGAL's corefinement, one solid after another)
/// into `result`, a closed triangle mesh oriented outward. Each solid must
/// be a closed, manifold triangle surface that does not cross itself and
/// bounds a volume (its faces may face either way: each is oriented outward
/// first); degenerate triangles (no area) are removed first. Empty, or the
/// reason as a sentence naming the solid (1-based); `result` is then left
/// empty. Solids that do not overlap stay apart in one mesh.
std::string solidUnion(const std::vector<TriangleMesh>& solids, TriangleMesh& result);

/// `solid` less all of `cutters` (joined first, then cut out at once), into `result`, a closed triangle
/// mesh oriented outward (several pieces where the cutters part it; empty
/// where they take it all). Each solid must be as for solidUnion. Empty, or
/// the reason ("cannot cut the solid: ...", "cannot cut with cutter 2 of 3:
/// ..."); `result` is then left empty.
std::string solidDifference(
  const TriangleMesh& solid, const std::vector<TriangleMesh>& cutters, TriangleMesh& result);

} // namespace lk
