/**
 * @class   vtkLKMeshRepairFilter
 * @brief   Make a triangle soup a manifold, consistently oriented triangle mesh.
 *
 * Polygons are triangulated first; vertex and line cells are dropped with a
 * warning. The repair itself is CGAL's (see core/ManifoldRepair.h): duplicate
 * points merged, degenerate faces removed, non-manifold vertices and edges
 * split, orientation made consistent and, for closed components, outward.
 * The result loads into a CGAL Surface_mesh.
 *
 * Attributes are carried as vtkCleanPolyData carries them: an output point
 * takes the point data of the input point at its position (the lowest id
 * among duplicates merged into it; a split vertex's copies all take it), an
 * output triangle the cell data of the input cell it came from (the one with
 * the same three positions). A point or face the repair made takes the data
 * of the input triangle nearest it (interpolated at the point; id arrays are
 * then left out, as VTK's interpolating filters leave them). Normals are not
 * carried, because the repair may turn faces over; recompute them
 * (vtkPolyDataNormals). The input's field data (a SPACE tag, for example) is
 * passed on.
 *
 * The output's field data holds what was done: MergedPoints,
 * RemovedDegenerateFaces, SplitNonManifoldVertices, Components, BoundaryEdges.
 */
#ifndef vtkLKMeshRepairFilter_h
#define vtkLKMeshRepairFilter_h

#include "LatticeKitFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class LATTICEKITFILTERS_EXPORT vtkLKMeshRepairFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkLKMeshRepairFilter* New();
  vtkTypeMacro(vtkLKMeshRepairFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkLKMeshRepairFilter() = default;
  ~vtkLKMeshRepairFilter() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkLKMeshRepairFilter(const vtkLKMeshRepairFilter&) = delete;
  void operator=(const vtkLKMeshRepairFilter&) = delete;
};

#endif
