/**
 * @class   vtkLKQuadPairingFilter
 * @brief   Pairs the triangles of a lattice into quads where the pair is
 *          near-rectangular (seed 004, sections 3.3.2 and 3.3.3).
 *
 * Input: a manifold triangle lattice, e.g. output 0 of vtkLKLatticeFitFilter
 * with QuadPairing off, or any decimated mesh. Line cells of the input on
 * lattice edges are feature edges: they are never removed, and are passed to
 * the output with their cell data. Two triangles across a non-feature edge
 * become a quad when the two angles facing the edge are near right
 * (|cos a| + |cos b| < RightAngleTolerance, eq. 3.15), the quad's angles at
 * the edge's ends differ by less than AngleSumTolerance radians (eq. 3.16)
 * and the dihedral angle is at most MaximumDihedralAngle degrees; candidates
 * are taken greedily, cheapest first, each triangle once. The cost of an
 * edge is (1 - cos dihedral) x its squared length (see
 * core/include/latticekit/QuadPairing.h; vtkLKLatticeFitFilter uses the
 * QEM cost of the edge instead).
 *
 * Output: the lattice with quads and the unpaired triangles (same points),
 * the input's line cells first; cell data "InputCellId" (for faces: the first
 * of the triangles it came from); field data Quads and Triangles.
 */
#ifndef vtkLKQuadPairingFilter_h
#define vtkLKQuadPairingFilter_h

#include "LatticeKitFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class LATTICEKITFILTERS_EXPORT vtkLKQuadPairingFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkLKQuadPairingFilter* New();
  vtkTypeMacro(vtkLKQuadPairingFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// S1 of eq. 3.15 (default 0.5), S2 of eq. 3.16 in radians (default 0.5),
  /// the largest dihedral angle in degrees (default 30).
  vtkSetMacro(RightAngleTolerance, double);
  vtkGetMacro(RightAngleTolerance, double);
  vtkSetMacro(AngleSumTolerance, double);
  vtkGetMacro(AngleSumTolerance, double);
  vtkSetMacro(MaximumDihedralAngle, double);
  vtkGetMacro(MaximumDihedralAngle, double);
  ///@}

protected:
  vtkLKQuadPairingFilter() = default;
  ~vtkLKQuadPairingFilter() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double RightAngleTolerance = 0.5;
  double AngleSumTolerance = 0.5;
  double MaximumDihedralAngle = 30.0;

private:
  vtkLKQuadPairingFilter(const vtkLKQuadPairingFilter&) = delete;
  void operator=(const vtkLKQuadPairingFilter&) = delete;
};

#endif
