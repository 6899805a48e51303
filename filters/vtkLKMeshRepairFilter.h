/**
 * @class   vtkLKMeshRepairFilter
 * @brief   Make a triangle soup a manifold, consistently oriented triangle mesh.
 *
 * Polygons are triangulated first; vertex and line cells are dropped with a
 * warning. The repair itself is CGAL's (see core/ManifoldRepair.h): duplicate
 * points merged, degenerate faces removed, non-manifold vertices and edges
 * split, orientation made consistent and, for closed components, outward.
 * The result loads into a CGAL Surface_mesh. Point and cell attributes are not
 * carried (points may be merged or split).
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
