/**
 * @class   vtkLKBezierIFSFilter
 * @brief   Draws a Bezier curve or surface as the attractor of an iterated
 *          function system (seed 003), deterministically or by the chaos game.
 *
 * Input: the control points (the points of any vtkPointSet; cells are
 * ignored). CURVE: the n + 1 points are the control polygon of a degree-n
 * curve. SURFACE: NetDimensions (nu, nv) points, u-major (point i * nv + j is
 * P_ij), a surface of degree (nu - 1, nv - 1); bicubic with 4 x 4.
 * QUADRATIC_PLANAR: 3 non-collinear points, drawn by the paper's direct
 * affine IFS in their plane (section 4).
 *
 * The maps (see core/include/latticekit/BezierIFS.h): the Bernstein curve in
 * R^(n+1) (surface: R^((nu)(nv))) is split at the break points (SetSplitParameter
 * for two maps, SetNumberOfMaps for k equal parts, or SetBreakPoints for any
 * increasing list in (0, 1)); surfaces use every pair of u and v parts.
 *
 * DETERMINISTIC (default): every composition of Depth maps applied to the
 * base figure (the segment B(0) B(1); the square's corners for surfaces):
 * the output is a polyline through the images (curves) or one quad per
 * image (surfaces, shared corners merged).
 * CHAOS_GAME: NumberOfPoints points, maps chosen with the probabilities
 * (SetProbabilities; default equal) by a generator seeded with RandomSeed;
 * the output is vertices with point data "HitDensity": the chaos game's hit
 * count in the point's cell of a DensityBins (x DensityBins) grid in
 * parameter space, divided by the mean count, so a uniform measure reads 1
 * everywhere (the invariant measure the paper proposes as a texture).
 * Every output point has point data "Parameter" (t, or u and v).
 *
 * Bad input (wrong number of control points, breaks outside (0, 1) or not
 * increasing, probabilities of the wrong count or not summing to 1,
 * collinear quadratic control points) gives a VTK error and an empty output.
 */
#ifndef vtkLKBezierIFSFilter_h
#define vtkLKBezierIFSFilter_h

#include "LatticeKitFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <vector>

class vtkDoubleArray;

class LATTICEKITFILTERS_EXPORT vtkLKBezierIFSFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkLKBezierIFSFilter* New();
  vtkTypeMacro(vtkLKBezierIFSFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Shape
  {
    CURVE = 0,
    SURFACE = 1,
    QUADRATIC_PLANAR = 2
  };
  enum Algorithm
  {
    DETERMINISTIC = 0,
    CHAOS_GAME = 1
  };

  ///@{
  vtkSetClampMacro(Shape, int, CURVE, QUADRATIC_PLANAR);
  vtkGetMacro(Shape, int);
  void SetShapeToCurve() { this->SetShape(CURVE); }
  void SetShapeToSurface() { this->SetShape(SURFACE); }
  void SetShapeToQuadraticPlanar() { this->SetShape(QUADRATIC_PLANAR); }
  vtkSetClampMacro(Algorithm, int, DETERMINISTIC, CHAOS_GAME);
  vtkGetMacro(Algorithm, int);
  void SetAlgorithmToDeterministic() { this->SetAlgorithm(DETERMINISTIC); }
  void SetAlgorithmToChaosGame() { this->SetAlgorithm(CHAOS_GAME); }
  ///@}

  ///@{
  /// Control net size for SURFACE (default 4 x 4).
  vtkSetVector2Macro(NetDimensions, int);
  vtkGetVector2Macro(NetDimensions, int);
  ///@}

  ///@{
  /// The break points. SetSplitParameter(t): two maps, [0, t] and [t, 1]
  /// (default t = 1/2). SetNumberOfMaps(k): k equal parts, k from 2 to
  /// 10,000 (a surface's maps are k x k). SetBreakPoints: any list. All are
  /// validated when the filter runs.
  void SetSplitParameter(double t);
  void SetNumberOfMaps(int k);
  void SetBreakPoints(vtkDoubleArray* breaks);
  int GetNumberOfBreakPoints() const { return static_cast<int>(this->Breaks.size()); }
  double GetBreakPoint(int i) const { return this->Breaks[static_cast<std::size_t>(i)]; }
  ///@}

  ///@{
  /// Map probabilities for the chaos game, one per map in the order of the
  /// maps (surfaces: u part major). Empty (default): all equal.
  void SetProbabilities(vtkDoubleArray* p);
  ///@}

  ///@{
  vtkSetClampMacro(Depth, int, 0, 24);
  vtkGetMacro(Depth, int);
  vtkSetClampMacro(NumberOfPoints, vtkIdType, 1, VTK_ID_MAX);
  vtkGetMacro(NumberOfPoints, vtkIdType);
  vtkSetMacro(RandomSeed, int);
  vtkGetMacro(RandomSeed, int);
  vtkSetClampMacro(DensityBins, int, 1, 4096);
  vtkGetMacro(DensityBins, int);
  ///@}

protected:
  vtkLKBezierIFSFilter() = default;
  ~vtkLKBezierIFSFilter() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Shape = CURVE;
  int Algorithm = DETERMINISTIC;
  int NetDimensions[2] = { 4, 4 };
  std::vector<double> Breaks{ 0.5 };
  int RefusedNumberOfMaps = 0; ///< SetNumberOfMaps outside 2..10,000 (reported when the filter runs)
  std::vector<double> Probabilities;
  int Depth = 6;
  vtkIdType NumberOfPoints = 10000;
  int RandomSeed = 5489;
  int DensityBins = 64;

private:
  vtkLKBezierIFSFilter(const vtkLKBezierIFSFilter&) = delete;
  void operator=(const vtkLKBezierIFSFilter&) = delete;
};

#endif
