#include "latticekit/ManifoldRepair.h"
#include "latticekit/PinchedVertices.h"
#include "latticekit/PointHash.h"
#include "latticekit/PolygonMesh.h"
#include "SurfaceMeshConversion.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/manifoldness.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <array>
#include <functional>
#include <unordered_map>
#include <iterator>
#include <stdexcept>
#include <sstream>
#include <utility>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;

namespace lk
{

namespace
{
using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Mesh = CGAL::Surface_mesh<Point>;
using Polygon = std::vector<std::size_t>;
const char* const kNotAPolygonMesh = "the triangles do not form a manifold, consistently oriented mesh "
                                     "(non-manifold edge or vertex, or inconsistent orientation)";

template <typename PolygonT>
void toSoup(const TriangleMesh& mesh, std::vector<Point>& points, std::vector<PolygonT>& polygons)
{
  points.reserve(mesh.points.size());
  for (const Vec3& p : mesh.points)
  {
    points.emplace_back(p.x(), p.y(), p.z());
  }
  polygons.reserve(mesh.triangles.size());
  for (const Triangle& t : mesh.triangles)
  {
    polygons.push_back({ static_cast<std::size_t>(t[0]), static_cast<std::size_t>(t[1]),
      static_cast<std::size_t>(t[2]) });
  }
}

/// merge_duplicate_points_in_polygon_soup's result (each point where it
/// first occurs, the triangles renumbered), from a hash table instead of
/// its std::map: 0.2 s instead of 2.2 on a CT's 1.5 million points. Returns
/// the number of points merged.
std::size_t mergeEqualPoints(std::vector<Point>& points, std::vector<IndexTriangle>& triangles)
{
  struct Hash
  {
    std::size_t operator()(const Point& p) const { return hashCoordinates(p.x(), p.y(), p.z()); }
  };
  struct Equal
  {
    bool operator()(const Point& a, const Point& b) const { return a.x() == b.x() && a.y() == b.y() && a.z() == b.z(); }
  };
  std::unordered_map<Point, std::size_t, Hash, Equal> first;
  first.reserve(points.size());
  std::vector<std::size_t> index(points.size());
  std::vector<Point> unique;
  unique.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const auto it = first.emplace(points[i], unique.size()).first;
    if (it->second == unique.size())
      unique.push_back(points[i]);
    index[i] = it->second;
  }
  const std::size_t merged = points.size() - unique.size();
  if (merged == 0)
    return 0;
  for (IndexTriangle& t : triangles)
    for (std::size_t& v : t)
      v = index[v];
  points.swap(unique);
  return merged;
}

/// Whether two triangles have the same three points (in any order), as
/// merge_duplicate_polygons_in_polygon_soup finds them once equal points
/// are merged. Sorting takes a fifth of that function's time, which on a
/// scan's surface finds none.
bool hasDuplicateTriangles(const std::vector<IndexTriangle>& triangles)
{
  std::vector<IndexTriangle> sorted(triangles);
  for (IndexTriangle& t : sorted)
    std::sort(t.begin(), t.end());
  std::sort(sorted.begin(), sorted.end());
  return std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
}

double componentSignedVolume(const Mesh& sm, const std::vector<Mesh::Face_index>& faces)
{
  double v = 0.0;
  for (auto f : faces)
  {
    auto h = sm.halfedge(f);
    const Point& a = sm.point(sm.source(h));
    const Point& b = sm.point(sm.target(h));
    const Point& c = sm.point(sm.target(sm.next(h)));
    v += CGAL::to_double(a.x() * (b.y() * c.z() - b.z() * c.y()) -
      a.y() * (b.x() * c.z() - b.z() * c.x()) + a.z() * (b.x() * c.y() - b.y() * c.x()));
  }
  return v / 6.0;
}
} // namespace

RepairReport repairToManifold(TriangleMesh& mesh, const std::function<bool(double)>& progress)
{
  const std::string problem = validateTriangleMesh(mesh);
  if (!problem.empty())
  {
    throw std::invalid_argument("repairToManifold: " + problem);
  }
  RepairReport report;
  report.inputTriangles = mesh.triangles.size();
  // The fractions are the shares of the time the steps took on 3 million
  // triangles (the CT head resampled to 0.5 mm voxels, 4.6 s): the soup's
  // repair and making the Surface_mesh a little over a fifth each.
  auto done = [&](double fraction) {
    if (progress && !progress(fraction))
      report.stopped = true;
    return !report.stopped;
  };

  // Triangles as arrays: a vector per triangle cost a fifth of the soup
  // repair's time in malloc and free on a CT's surface.
  std::vector<Point> points;
  std::vector<IndexTriangle> polygons;
  toSoup(mesh, points, polygons);
  const std::size_t pointsBefore = points.size();
  if (!done(0.04))
    return report;
  // repair_polygon_soup's steps for triangles: merge equal points, drop the
  // triangles that then repeat a point (simplify_polygons and
  // split_pinched_polygons for a triangle), then duplicate triangles and
  // points no triangle uses.
  // (merge_duplicate_points_in_polygon_soup's result from a hash table;
  // merge_duplicate_polygons_in_polygon_soup only where two triangles have
  // the same points: one or two on a CT's skin, none on its bone.)
  mergeEqualPoints(points, polygons);
  polygons.erase(std::remove_if(polygons.begin(), polygons.end(),
                   [](const IndexTriangle& t) { return t[0] == t[1] || t[1] == t[2] || t[0] == t[2]; }),
    polygons.end());
  if (hasDuplicateTriangles(polygons))
    PMP::merge_duplicate_polygons_in_polygon_soup(points, polygons);
  PMP::remove_isolated_points_in_polygon_soup(points, polygons);
  report.mergedPoints = pointsBefore > points.size() ? pointsBefore - points.size() : 0;
  report.removedSoupPolygons = report.inputTriangles - polygons.size();
  if (polygons.empty())
  {
    throw std::runtime_error("repairToManifold: every triangle is degenerate");
  }
  if (!done(0.42))
    return report;
  const std::size_t pointsBeforeOrient = points.size();
  // A marching-cubes surface needs no orienting, only its pinched vertices
  // split: the same soup as orient_polygon_soup makes, in a thirtieth of
  // the time (PinchedVertices.h).
  if (const auto copies = splitPinchedVerticesOfOrientedSoup(polygons, points.size()))
  {
    for (const std::size_t v : *copies)
      points.push_back(points[v]);
  }
  else
    PMP::orient_polygon_soup(points, polygons);
  report.splitNonManifold = points.size() - pointsBeforeOrient;
  if (!done(0.57))
    return report;

  Mesh sm;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, sm);
  if (!done(0.80))
    return report;
  const std::size_t facesBefore = sm.number_of_faces();
  // Counted before: a cap is removed by flipping the edge under it, which
  // leaves the number of faces as it was.
  std::size_t degenerate = 0;
  for (const auto f : faces(sm))
    degenerate += PMP::is_degenerate_triangle_face(f, sm) ? 1 : 0;
  PMP::remove_degenerate_faces(sm);
  sm.collect_garbage();
  report.removedDegenerateFaces = std::max(degenerate, facesBefore - sm.number_of_faces());
  report.splitNonManifold += PMP::duplicate_non_manifold_vertices(sm);
  if (sm.number_of_faces() == 0)
  {
    throw std::runtime_error("repairToManifold: nothing is left after removing degenerate faces");
  }

  if (!done(0.84))
    return report;
  // Orientation, component by component.
  auto fccmap = sm.add_property_map<Mesh::Face_index, std::size_t>("f:cc", 0).first;
  report.components = PMP::connected_components(sm, fccmap);
  std::vector<std::vector<Mesh::Face_index>> byComponent(report.components);
  for (auto f : sm.faces())
  {
    byComponent[fccmap[f]].push_back(f);
  }
  bool anyFlip = false;
  std::vector<Mesh::Face_index> toFlip;
  for (const auto& faces : byComponent)
  {
    if (componentSignedVolume(sm, faces) < 0.0)
    {
      toFlip.insert(toFlip.end(), faces.begin(), faces.end());
      anyFlip = true;
    }
  }
  if (anyFlip)
  {
    PMP::reverse_face_orientations(toFlip, sm);
  }
  sm.remove_property_map(fccmap);
  if (CGAL::is_closed(sm))
  {
    // Nested closed components (a cavity inside bone) must face the other way.
    PMP::orient_to_bound_a_volume(sm);
  }

  if (!done(0.93))
    return report;
  report.boundaryEdges = static_cast<std::size_t>(
    std::count_if(sm.halfedges_begin(), sm.halfedges_end(), [&sm](Mesh::Halfedge_index h) { return sm.is_border(h); }));
  mesh = cgal::fromSurfaceMesh(sm);
  report.outputTriangles = mesh.triangles.size();
  report.outputPoints = mesh.points.size();
  report.closed = report.boundaryEdges == 0;
  return report;
}

std::string cgalSurfaceMeshProblem(const TriangleMesh& mesh)
{
  cgal::SurfaceMesh sm;
  return cgal::checkedSurfaceMesh(mesh, sm);
}

namespace cgal
{
std::string checkedSurfaceMesh(const TriangleMesh& mesh, SurfaceMesh& sm)
{
  std::string problem = validateTriangleMesh(mesh);
  if (!problem.empty())
  {
    return problem;
  }
  for (const Triangle& t : mesh.triangles)
  {
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
    {
      return "a triangle repeats a vertex";
    }
  }
  // Built face by face: a face that cannot be added (an edge with a third
  // face or two the same way round) or a vertex left with two fans is what
  // is_polygon_soup_a_polygon_mesh refuses; the mesh is built once, not a
  // soup checked and then a mesh built from it (a sixth of the fit of a
  // whole skull).
  sm.clear();
  if (!toSurfaceMesh(mesh, sm))
  {
    return kNotAPolygonMesh;
  }
  // One pass over the mesh (is_non_manifold_vertex scans it once per vertex).
  std::vector<Mesh::Halfedge_index> pinched;
  PMP::non_manifold_vertices(sm, std::back_inserter(pinched));
  if (!pinched.empty())
  {
    return kNotAPolygonMesh;
  }
  if (!CGAL::is_valid_polygon_mesh(sm))
  {
    return "CGAL::is_valid_polygon_mesh fails";
  }
  for (auto f : sm.faces())
  {
    if (PMP::is_degenerate_triangle_face(f, sm))
    {
      return "the mesh has a degenerate (zero-area) triangle";
    }
  }
  return {};
}
} // namespace cgal

std::size_t countBoundaryEdges(const TriangleMesh& mesh)
{
  std::vector<std::pair<std::int64_t, std::int64_t>> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (const Triangle& t : mesh.triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      edges.emplace_back(std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]));
    }
  }
  std::sort(edges.begin(), edges.end());
  std::size_t boundary = 0;
  for (std::size_t i = 0; i < edges.size();)
  {
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j] == edges[i])
    {
      ++j;
    }
    boundary += (j - i == 1) ? 1 : 0;
    i = j;
  }
  return boundary;
}

double signedVolume(const TriangleMesh& mesh)
{
  double v = 0.0;
  for (const Triangle& t : mesh.triangles)
  {
    const Vec3& a = mesh.points[static_cast<std::size_t>(t[0])];
    const Vec3& b = mesh.points[static_cast<std::size_t>(t[1])];
    const Vec3& c = mesh.points[static_cast<std::size_t>(t[2])];
    v += a.dot(b.cross(c));
  }
  return v / 6.0;
}

std::string polygonIndexProblem(const PolygonMesh& mesh)
{
  if (mesh.faces.empty())
  {
    return "the lattice has no faces";
  }
  const auto n = static_cast<std::int64_t>(mesh.points.size());
  std::vector<char> used(mesh.points.size(), 0);
  std::ostringstream os;
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
  {
    const auto& face = mesh.faces[f];
    if (face.size() < 3)
    {
      os << "face " << f << " has " << face.size() << " vertices (at least 3 are needed)";
      return os.str();
    }
    for (std::size_t i = 0; i < face.size(); ++i)
    {
      const auto id = face[i];
      if (id < 0 || id >= n)
      {
        os << "face " << f << " refers to point " << id << ", but the lattice has " << n << " points";
        return os.str();
      }
      const Vec3& p = mesh.points[static_cast<std::size_t>(id)];
      if (!isUsablePoint(p))
      {
        os << "point " << id << " has " << unusablePointReason(p);
        return os.str();
      }
      for (std::size_t j = i + 1; j < face.size(); ++j)
      {
        if (face[j] == id)
        {
          os << "face " << f << " repeats vertex " << id;
          return os.str();
        }
      }
      used[static_cast<std::size_t>(id)] = 1;
    }
    if (!(newellVector(mesh, f).norm() > 0.0))
    {
      os << "face " << f << " has zero area";
      return os.str();
    }
  }
  for (std::size_t i = 0; i < used.size(); ++i)
  {
    if (!used[i])
    {
      os << "point " << i << " is isolated (no face uses it)";
      return os.str();
    }
  }
  return {};
}

std::string latticeProblem(const PolygonMesh& mesh)
{
  const std::string problem = polygonIndexProblem(mesh);
  if (!problem.empty())
    return problem;
  std::vector<Polygon> polygons;
  polygons.reserve(mesh.faces.size());
  for (const auto& face : mesh.faces)
  {
    polygons.emplace_back(face.begin(), face.end());
  }
  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons))
  {
    return "the lattice is not a manifold, consistently oriented surface "
           "(an edge with more than two faces, a pinched vertex, or faces oriented against each other)";
  }
  return {};
}

} // namespace lk
