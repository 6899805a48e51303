/**
 * @class   vtkLKWrinklyNetSource
 * @brief   Example control meshes for vtkLKWrinklySurfaceFilter: the
 *          regular (2-direction), N-direction and annular nets of the
 *          wrinkly-surface paper's figures 12 and 13.
 *
 * Output: a flat polygon mesh (z = 0) with point data "Height" (uniform in
 * [-HeightAmplitude, HeightAmplitude]) and "RGB" (doubles in [0, 1]), both
 * from a fixed pseudo-random sequence (Seed), so every run gives the same
 * net. The outermost ring of points is virtual (the filter's default).
 * - Regular: CellsU x CellsV cells.
 * - Polygon: a central cell with Sides corners, Rings quads outwards and
 *   EdgeCells quads along each side; 2N sides give the N-direction net
 *   (6: 3-direction, 8: 4-direction). Odd Sides give a net whose axes fall
 *   into one group, which the filter refuses.
 * - Annular: Spokes spokes and Rings rings around a central polygon.
 * See core/include/latticekit/WrinklyNets.h.
 */
#ifndef vtkLKWrinklyNetSource_h
#define vtkLKWrinklyNetSource_h

#include "LatticeKitFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class LATTICEKITFILTERS_EXPORT vtkLKWrinklyNetSource : public vtkPolyDataAlgorithm
{
public:
  static vtkLKWrinklyNetSource* New();
  vtkTypeMacro(vtkLKWrinklyNetSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum NetType
  {
    Regular = 0,
    Polygon = 1,
    Annular = 2
  };

  ///@{
  vtkSetClampMacro(NetType, int, Regular, Annular);
  vtkGetMacro(NetType, int);
  void SetNetTypeToRegular() { this->SetNetType(Regular); }
  void SetNetTypeToPolygon() { this->SetNetType(Polygon); }
  void SetNetTypeToAnnular() { this->SetNetType(Annular); }
  ///@}

  ///@{
  /// Sizes (see the class description).
  vtkSetClampMacro(CellsU, int, 2, 1000);
  vtkGetMacro(CellsU, int);
  vtkSetClampMacro(CellsV, int, 2, 1000);
  vtkGetMacro(CellsV, int);
  vtkSetClampMacro(Sides, int, 3, 64);
  vtkGetMacro(Sides, int);
  vtkSetClampMacro(Rings, int, 1, 1000);
  vtkGetMacro(Rings, int);
  vtkSetClampMacro(EdgeCells, int, 1, 1000);
  vtkGetMacro(EdgeCells, int);
  vtkSetClampMacro(Spokes, int, 3, 1000);
  vtkGetMacro(Spokes, int);
  ///@}

  ///@{
  /// Point spacing, height amplitude and the seed of the pseudo-random values.
  vtkSetClampMacro(Spacing, double, 1e-9, 1e9);
  vtkGetMacro(Spacing, double);
  vtkSetMacro(HeightAmplitude, double);
  vtkGetMacro(HeightAmplitude, double);
  vtkSetMacro(Seed, int);
  vtkGetMacro(Seed, int);
  ///@}

protected:
  vtkLKWrinklyNetSource();
  ~vtkLKWrinklyNetSource() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int NetType = Regular;
  int CellsU = 8;
  int CellsV = 8;
  int Sides = 6;
  int Rings = 3;
  int EdgeCells = 1;
  int Spokes = 12;
  double Spacing = 1.0;
  double HeightAmplitude = 0.3;
  int Seed = 1;

private:
  vtkLKWrinklyNetSource(const vtkLKWrinklyNetSource&) = delete;
  void operator=(const vtkLKWrinklyNetSource&) = delete;
};

#endif
