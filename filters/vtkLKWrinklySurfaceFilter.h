/**
 * @class   vtkLKWrinklySurfaceFilter
 * @brief   Wrinkly surface (seed 000, Fujimoto and Ohno) from a control mesh:
 *          a Bezier base surface displaced along its normal by heights moved
 *          through the Iterated Shuffle Transformation.
 *
 * Input: a polygon control mesh (any cell sizes: the grid regions) whose
 * points are wrinkly control points. Point data:
 * - HeightArrayName (default "Height", 1 component): required;
 * - ColorArrayName (default "RGB", 3 components, values 0..1 or 0..255):
 *   optional, carried through the IST like the heights;
 * - OpacityArrayName (default "Opacity", 1 component): optional, the same;
 * - VirtualArrayName (default "Virtual", 1 component, nonzero = virtual):
 *   optional; without it the border points are virtual (no patch of their
 *   own, as the outermost ring of the paper's figures).
 * Every real point needs two to four links, and the mesh's global axes must
 * fall into two groups (section 3.1); otherwise the filter fails with the
 * reason (see core/include/latticekit/WrinklyGlobalAxes.h).
 *
 * Parameters: ShuffleU and ShuffleV (M_U, M_V), Iterations (K) or a
 * SamplingTolerance (a length; when above 0 it picks the smallest K whose
 * pieces are no longer than it on the largest patch: level of detail),
 * Alpha0 and Alpha1 (eq. 12, sum 1), Resolution (samples per patch side;
 * 0 = (2 max(M_U, M_V) + 1)^K, one per IST piece).
 *
 * Output: triangles of the displaced surface (eq. 15). Point data "Height"
 * (the IST'd height), "Normals" (base surface), the colour array (doubles, as
 * given) plus "Colors" (unsigned char RGB or RGBA for rendering) and the
 * opacity array when given. Cell data "ControlPointId" (the control point
 * whose patch holds the triangle). Field data "Iterations" (the K used).
 */
#ifndef vtkLKWrinklySurfaceFilter_h
#define vtkLKWrinklySurfaceFilter_h

#include "LatticeKitFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <string>

class LATTICEKITFILTERS_EXPORT vtkLKWrinklySurfaceFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkLKWrinklySurfaceFilter* New();
  vtkTypeMacro(vtkLKWrinklySurfaceFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Shuffle counts M_U, M_V (0 to 10, default 1).
  vtkSetClampMacro(ShuffleU, int, 0, 10);
  vtkGetMacro(ShuffleU, int);
  vtkSetClampMacro(ShuffleV, int, 0, 10);
  vtkGetMacro(ShuffleV, int);
  ///@}

  ///@{
  /// Iteration count K (0 to 12, default 3); ignored when SamplingTolerance > 0.
  vtkSetClampMacro(Iterations, int, 0, 12);
  vtkGetMacro(Iterations, int);
  ///@}

  ///@{
  /// Level of detail: largest IST piece length (0, the default, uses Iterations).
  vtkSetMacro(SamplingTolerance, double);
  vtkGetMacro(SamplingTolerance, double);
  ///@}

  ///@{
  /// Blend of the U->V and V->U orders (eq. 12); must add up to 1 (default 0.5, 0.5).
  vtkSetMacro(Alpha0, double);
  vtkGetMacro(Alpha0, double);
  vtkSetMacro(Alpha1, double);
  vtkGetMacro(Alpha1, double);
  ///@}

  ///@{
  /// Samples per patch side (0, the default: one per IST piece).
  vtkSetClampMacro(Resolution, int, 0, 4096);
  vtkGetMacro(Resolution, int);
  ///@}

  ///@{
  /// Names of the input point arrays.
  vtkSetStdStringFromCharMacro(HeightArrayName);
  vtkGetCharFromStdStringMacro(HeightArrayName);
  vtkSetStdStringFromCharMacro(ColorArrayName);
  vtkGetCharFromStdStringMacro(ColorArrayName);
  vtkSetStdStringFromCharMacro(OpacityArrayName);
  vtkGetCharFromStdStringMacro(OpacityArrayName);
  vtkSetStdStringFromCharMacro(VirtualArrayName);
  vtkGetCharFromStdStringMacro(VirtualArrayName);
  ///@}

  /// The K used by the last update (from Iterations or the tolerance).
  vtkGetMacro(UsedIterations, int);

protected:
  vtkLKWrinklySurfaceFilter() = default;
  ~vtkLKWrinklySurfaceFilter() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int ShuffleU = 1;
  int ShuffleV = 1;
  int Iterations = 3;
  double SamplingTolerance = 0.0;
  double Alpha0 = 0.5;
  double Alpha1 = 0.5;
  int Resolution = 0;
  int UsedIterations = 0;
  std::string HeightArrayName = "Height";
  std::string ColorArrayName = "RGB";
  std::string OpacityArrayName = "Opacity";
  std::string VirtualArrayName = "Virtual";

private:
  vtkLKWrinklySurfaceFilter(const vtkLKWrinklySurfaceFilter&) = delete;
  void operator=(const vtkLKWrinklySurfaceFilter&) = delete;
};

#endif
