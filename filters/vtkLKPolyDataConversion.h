#pragma once
/// \file vtkLKPolyDataConversion.h
/// Private: conversion between vtkPolyData and the cores' lk::TriangleMesh,
/// with the input checks every latticekit filter shares.

#include "latticekit/LatticeSimplification.h"
#include "latticekit/PolygonMesh.h"
#include "latticekit/TriangleMesh.h"

#include <vtkSmartPointer.h>

#include <string>

class vtkPolyData;

namespace lkvtk
{

/// Copies the triangles of pd into mesh. Returns an empty string on success,
/// otherwise a sentence for vtkErrorMacro (empty input, vertex/line/strip
/// cells, polygons that are not triangles, NaN or infinite coordinates).
std::string toTriangleMesh(vtkPolyData* pd, lk::TriangleMesh& mesh);

/// Copies the polygons of pd (any number of vertices each) into mesh, with
/// the same input checks as toTriangleMesh but for polygons.
std::string toPolygonMesh(vtkPolyData* pd, lk::PolygonMesh& mesh);

/// `pd`'s cells that are not polygons, as the end of a sentence ("3 vertex,
/// 0 line and 2 strip cells (vtkTriangleFilter turns strips into
/// triangles)"); empty when it has none. For filters that take polygons.
std::string otherThanPolygons(vtkPolyData* pd);

/// What makes `pd` no surface to work on, as a clause for vtkErrorMacro
/// ("the input has no surface (no polygons or strips)", "point 5 is not
/// finite", "every point is in one place", "the surface is too large to
/// measure (...)"); empty when it is one.
std::string surfaceProblem(vtkPolyData* pd);

/// `pd`'s polygons and strips as triangles (polygons fanned, strips split;
/// vertices and lines left out), on its points.
vtkSmartPointer<vtkPolyData> facesAsTriangles(vtkPolyData* pd);

/// A vtkPolyData with the mesh's points (double precision) and triangles.
vtkSmartPointer<vtkPolyData> fromTriangleMesh(const lk::TriangleMesh& mesh);

/// The mesh edges a set of polylines runs along (sorted, unique). Line points
/// name mesh points by point data "MeshPointId" (any integer type) or by
/// coordinates equal to a mesh point's (within 1e-9 of the diagonal).
/// Returns an empty string, or a sentence for vtkErrorMacro. Whether
/// consecutive points are joined by an edge is left to the caller.
std::string lineEdges(vtkPolyData* lines, vtkPolyData* mesh, std::vector<lk::EdgeKey>& out);

} // namespace lkvtk
