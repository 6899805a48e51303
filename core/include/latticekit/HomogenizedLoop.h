#pragma once
/// \file HomogenizedLoop.h
/// Homogenized Loop subdivision (seed 001, Sato and Yoshida): Loop's masks
/// (eqs. 2.1 to 2.4, beta of eq. 2.3, 3/16 at valence 3) applied to 4D
/// homogeneous points (w x, w y, w z, w) (eq. 3.1), projected back by
/// dividing by w (eq. 3.2) after each level; boundary rules (eqs. 4.1, 4.2)
/// on meshes with holes.
///
/// Weights, and exactly how they act at every level (all must be finite and
/// above 0; 1 everywhere is plain Loop subdivision, identical to
/// vtkLoopSubdivisionFilter):
/// - vertex weight w_v: the vertex's homogeneous coordinate is (w_v x_v, w_v).
///   New points carry the w the masks give them into the next level.
/// - edge weight c_e: multiplies the terms of the edge's own end points in
///   the masks that reach across it. The edge point of e = (a, b) is
///     E = sum over the faces f beside e of  w_f (c_e 3/16 (A + B) + 1/8 C_f)
///   (C_f: f's third vertex, capitals homogeneous), and in the vertex point
///   of a every neighbour b is weighted by c_(a,b). c > 1 pulls the edge point
///   towards the edge and its end points towards each other along it: the
///   surface is drawn onto the edge and sharpened there. Both halves of e
///   inherit c_e at the next level; new inner edges get 1.
/// - face weight w_f: multiplies every term a face contributes. Written per
///   face, the vertex point of v (k faces, k neighbours) is
///     V = sum over the faces f = (v, a, b) around v of
///         w_f ((1 - k beta) / k V + beta / 2 (c_(v,a) A + c_(v,b) B)),
///   which with all weights 1 is Loop's (1 - k beta) v + beta sum p_j. A region
///   of equal face weights keeps its shape (homogeneous points are scale
///   invariant); at its border its faces outweigh their neighbours, so the
///   surface is drawn towards the weighted faces. The four children of f
///   inherit w_f.
/// - boundaries (eqs. 4.1, 4.2): E = c_e (A + B) / 2 and
///   V = 3/4 V + 1/8 (c_(v,p) P + c_(v,q) Q) with p, q the boundary
///   neighbours: the boundary curve depends on the boundary alone (with
///   weights 1 it is the cubic B-spline of the boundary polygon).
/// Point attributes ride along as extra homogeneous coordinates (w a), so they
/// are interpolated by the same rational masks; each output triangle records
/// the input triangle it lies in.

#include "latticekit/LatticeSimplification.h"
#include "latticekit/TriangleMesh.h"

#include <functional>
#include <utility>
#include <vector>

namespace lk
{

struct HomogenizedLoopInput
{
  TriangleMesh mesh;
  std::vector<double> vertexWeights;                      ///< empty: all 1
  std::vector<std::pair<EdgeKey, double>> edgeWeights;    ///< missing edges: 1
  std::vector<double> faceWeights;                        ///< empty: all 1
  int attributeComponents = 0;                            ///< point attributes, components each
  std::vector<double> attributes;                         ///< points x components
};

struct HomogenizedLoopOutput
{
  TriangleMesh mesh;
  std::vector<double> weights;            ///< homogeneous w of every output point
  std::vector<double> attributes;         ///< interpolated point attributes
  std::vector<std::int64_t> parentFace;   ///< the input triangle of every output triangle
};

/// `levels` subdivisions. `progress` gets the fraction of the work done
/// after each level (a level has four times the triangles of the one
/// before) and may return false to stop (the result is then empty). Throws
/// std::invalid_argument, with the reason, for a mesh that is not a manifold
/// triangle mesh, weights that are not finite and above 0, weights of the
/// wrong count or on pairs that are not edges, or levels outside 0..6.
HomogenizedLoopOutput homogenizedLoop(const HomogenizedLoopInput& input, int levels,
  const std::function<bool(double)>& progress = {});

} // namespace lk
