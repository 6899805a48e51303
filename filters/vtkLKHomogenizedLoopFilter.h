/**
 * @class   vtkLKHomogenizedLoopFilter
 * @brief   Loop subdivision in 4D homogeneous coordinates with vertex, edge
 *          and face weights (seed 001, Sato and Yoshida).
 *
 * Input: a manifold triangle mesh, closed or with holes. Weights (all
 * optional, finite and above 0; 1 everywhere gives exactly the points of
 * vtkLoopSubdivisionFilter) come from arrays named WeightArrayName
 * (default "LoopWeight"):
 * - point data: vertex weights, the homogeneous w of each vertex;
 * - cell data on the triangles: face weights;
 * - cell data on line cells of the input lying on mesh edges: edge weights
 *   (a polyline gives its weight to each of its segments); line cells
 *   without the array get weight 1.
 * See core/include/latticekit/HomogenizedLoop.h for how each weight enters
 * the masks at every level: weights above 1 pull the surface towards the
 * weighted vertex, edge or face and sharpen it there. Boundaries follow eqs.
 * 4.1 and 4.2 (the boundary curve depends on the boundary alone).
 *
 * Output: the subdivided triangles, projected to 3D (eq. 3.2); every input
 * point data array interpolated by the same rational masks (same names and
 * types), plus "HomogeneousWeight" (the w of each point); the triangles'
 * cell data copied from the input triangle each lies in, plus
 * "InputCellId".
 */
#ifndef vtkLKHomogenizedLoopFilter_h
#define vtkLKHomogenizedLoopFilter_h

#include "LatticeKitFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <string>

class LATTICEKITFILTERS_EXPORT vtkLKHomogenizedLoopFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkLKHomogenizedLoopFilter* New();
  vtkTypeMacro(vtkLKHomogenizedLoopFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Levels of subdivision, 0 to 6 (default 1, as vtkLoopSubdivisionFilter).
  vtkSetClampMacro(NumberOfSubdivisions, int, 0, 6);
  vtkGetMacro(NumberOfSubdivisions, int);
  ///@}

  ///@{
  /// Name of the weight arrays (point data, triangle and line cell data).
  vtkSetStdStringFromCharMacro(WeightArrayName);
  vtkGetCharFromStdStringMacro(WeightArrayName);
  ///@}

protected:
  vtkLKHomogenizedLoopFilter() = default;
  ~vtkLKHomogenizedLoopFilter() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int NumberOfSubdivisions = 1;
  std::string WeightArrayName = "LoopWeight";

private:
  vtkLKHomogenizedLoopFilter(const vtkLKHomogenizedLoopFilter&) = delete;
  void operator=(const vtkLKHomogenizedLoopFilter&) = delete;
};

#endif
