#pragma once
/// \file vtkLKMeshPointIds.h
/// Private: lines that name a mesh's points by point data "MeshPointId" (the
/// stroke filter's feature lines, the cut's and the fit's line inputs, the
/// planner's cut_lines.vtp). VTK-only, so that the command-line tools can
/// check their files with it too.

#include <vtkType.h>

#include <string>

class vtkDataArray;
class vtkPolyData;

namespace lkvtk
{

/// The mesh point that line point `i` names by `ids` (its point data
/// MeshPointId, any numeric type), or -1 where the id is not a whole number
/// in 0 .. meshPoints - 1.
vtkIdType meshPointIdOf(vtkDataArray* ids, vtkIdType i, vtkIdType meshPoints);

/// Whether lines that name `mesh`'s points by point data MeshPointId lie on
/// the points they name: "" if they do (or carry no MeshPointId), else a
/// phrase naming the first point that lies off its mesh point by more than
/// 1e-4 of the mesh's size (lines made on another mesh, or on this one
/// before its points were renumbered). Ids outside the mesh are left to the
/// filters, which name them.
std::string linesOffTheirMeshPoints(vtkPolyData* lines, vtkPolyData* mesh);

} // namespace lkvtk
