#pragma once
/// \file vtkLKMeshPointIds.h
/// Private: lines that name a mesh's points by point data "MeshPointId" (the
/// stroke filter's feature lines, the cut's and the fit's line inputs, the
/// planner's cut_lines.vtp). VTK-only, so that the command-line tools can
/// check their files with it too.

#include <string>

class vtkPolyData;

namespace lkvtk
{

/// Whether lines that name `mesh`'s points by point data MeshPointId lie on
/// the points they name: "" if they do (or carry no MeshPointId), else a
/// phrase naming the first point that lies off its mesh point by more than
/// 1e-4 of the mesh's size (lines made on another mesh, or on this one
/// before its points were renumbered). Ids outside the mesh are left to the
/// filters, which name them.
std::string linesOffTheirMeshPoints(vtkPolyData* lines, vtkPolyData* mesh);

} // namespace lkvtk
