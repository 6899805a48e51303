#pragma once
/// \file PinchedVertices.h
/// The pinched vertices of a triangle soup that needs no orienting, split as
/// CGAL's orient_polygon_soup splits them. A marching-cubes surface is
/// oriented consistently already, but where the iso value meets voxels
/// exactly, merged points pinch it: a vertex where two cones meet at their
/// tips, an edge with four triangles where two sheets touch. CGAL's
/// orient_polygon_soup orients and then splits those; on a CT's surface its
/// orienting finds nothing to do and takes most of the repair's time (5 s of
/// 10 on the GE series' 1.5 million triangles: its edge map allocates per
/// vertex), where this takes 0.16 s and leaves the same soup.

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace lk
{
/// Three point indices.
using IndexTriangle = std::array<std::size_t, 3>;

/// For a soup whose triangles use points 0 .. pointCount - 1, none
/// repeating a point in itself: when every edge with exactly two triangles
/// has them in opposite directions, splits the pinched vertices and returns
/// the points to copy (new point pointCount + i is a copy of point
/// result[i]). Edges with three or more triangles are cut, as CGAL marks
/// them; a vertex whose triangles then form several fans, joined across
/// edges with one triangle each way, keeps it for the fan with the lowest
/// triangle, and each other fan, in the order of its lowest triangle, gets a
/// copy, vertex by vertex: the triangles come out as orient_polygon_soup
/// leaves them. Returns nothing and leaves the triangles unchanged when an
/// edge has its two triangles in the same direction: the soup needs
/// orienting (orient_polygon_soup) then. Throws std::invalid_argument for a
/// triangle that repeats a point or refers to one beyond pointCount.
std::optional<std::vector<std::size_t>> splitPinchedVerticesOfOrientedSoup(
  std::vector<IndexTriangle>& triangles, std::size_t pointCount);
} // namespace lk
