#pragma once
/// \file PieceContact.h
/// How a moved bone segment meets the bone beside it, which a surgeon asks
/// of every move: apart, and how far at the nearest; or overlapping (bone
/// through bone), how deep, and over how many vertices. A segment advanced
/// or turned into its neighbour cannot be placed so in the patient.

#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <array>
#include <memory>
#include <string>

namespace lkapp
{

/// Point x placed by a rigid transform, row-major 4x4 (the planner's
/// segment matrix).
std::array<double, 3> placedPoint(const std::array<double, 16>& m, const std::array<double, 3>& x);

/// One surface made ready for contact queries: a cell locator for distances
/// and, when it is closed (no border edge), outward face normals
/// (vtkPolyDataNormals, oriented) and a ray test (vtkSelectEnclosedPoints)
/// for inside. Built once per surface, asked at every move.
class ContactSurface
{
public:
  explicit ContactSurface(vtkPolyData* surface);
  ~ContactSurface();
  ContactSurface(const ContactSurface&) = delete;
  ContactSurface& operator=(const ContactSurface&) = delete;

  vtkPolyData* surface() const { return Surface; }
  /// Whether it is closed: only then does "inside" mean anything.
  bool closed() const { return Closed; }
  /// The distance from x to the surface and, with `inside`, whether x lies
  /// inside it (a closed surface; never for an open one): the side of the
  /// nearest face's outward normal where that is clear, a ray where x lies
  /// nearest an edge or a corner.
  double distance(const double x[3], bool* inside = nullptr) const;
  /// The distance from x to the nearest vertex (not less than distance()).
  double vertexDistance(const double x[3]) const;
  /// The surface's bounds, grown by `margin` on every side, hold x.
  bool nearBounds(const double x[3], double margin) const;

private:
  struct Tools;
  vtkSmartPointer<vtkPolyData> Surface;
  bool Closed = false;
  double Bounds[6] = { 0, 0, 0, 0, 0, 0 };
  std::unique_ptr<Tools> tools;
};

/// How `moved`, placed by `matrix` (row-major 4x4, rigid), meets `fixed`.
/// Both surfaces' vertices are tested against the other: a vertex deeper
/// than `touch` inside the other (both closed) makes an overlap, whose depth
/// is the deepest such vertex's distance to the other surface; otherwise
/// `gap` is the smallest vertex-to-surface distance either way (0 where they
/// touch, as the pieces of a cut do before a move). Vertex spacing bounds
/// how far these are from the exact surface-to-surface values.
struct Contact
{
  bool overlap = false;
  double gap = 0.0;    ///< apart: the nearest distance
  double depth = 0.0;  ///< overlapping: the deepest vertex's depth
  long long inside = 0; ///< overlapping: vertices of either inside the other
  bool known = true;   ///< false when either surface is open: no overlap can be told, only the gap
};
/// With `insidePoints`, the vertices inside the other are added to it, where
/// they are shown (the moved piece's placed by `matrix`): where the bone
/// runs through bone.
Contact contactOf(const ContactSurface& moved, const std::array<double, 16>& matrix, const ContactSurface& fixed,
  double touch, vtkPoints* insidePoints = nullptr);

/// "1.23 mm apart", "overlapping 2.10 mm deep (412 vertices inside)", or
/// "1.23 mm apart at the nearest vertex (piece 0 is open: an overlap cannot be told)".
std::string contactText(const Contact& contact);

} // namespace lkapp
