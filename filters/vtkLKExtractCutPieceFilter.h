/**
 * @class   vtkLKExtractCutPieceFilter
 * @brief   One piece of a cut (vtkLKClosedLineCutFilter's output), and the
 *          cut lines along its edges as feature lines for a lattice fit.
 *
 * Input: a cut, all its pieces in one polydata with cell data "RegionId"
 * (the piece of each cell) and, when capped, "Cap" (1 on cap faces).
 *
 * Output 0: the cells of piece `Piece`, in the cut's order (vertices, lines,
 * polygons, strips, each kind in the order it has there), and the points they
 * use, in the cut's order; with PassAttributes (default on) the cut's point
 * and cell data, always its field data (a SPACE tag passes). The same cut
 * gives the same piece, byte for byte, every time. (vtkThreshold on
 * RegionId and vtkGeometryFilter give the same cells, but in VTK 9.1 both run
 * on threads and list them in another order from run to run: files differ
 * between two exports of one plan, and so do lattices fitted on them.)
 *
 * Output 1 (GetCutLinesOutput): where the cut went through the piece's
 * surface: the edges of its faces that are not cap faces, with no second such
 * face in the piece, and whose other side (an edge with the same two end
 * points, met by a face of another piece or by another face of this one)
 * is in the cut too. Those are the cut lines (on a capped piece, where the
 * cap meets the bone; on an open one, its border along the cut); the input
 * surface's own border, if it had one, is not. They are chained into
 * polylines (a closed loop repeats its first point at its end; lines meet
 * only at their ends) whose point data "MeshPointId" names output 0's
 * points: the feature lines vtkLKLatticeFitFilter takes, so that
 * "cut, extract a piece, fit it with its cut lines locked" is one pipeline.
 * Field data "CutLineEdges" counts the edges.
 *
 * A Piece the cut does not have, or an empty input, gives empty outputs
 * (CutLineEdges 0); a cut without "RegionId" gives a VTK error and empty
 * outputs.
 */
#ifndef vtkLKExtractCutPieceFilter_h
#define vtkLKExtractCutPieceFilter_h

#include "LatticeKitFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class LATTICEKITFILTERS_EXPORT vtkLKExtractCutPieceFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkLKExtractCutPieceFilter* New();
  vtkTypeMacro(vtkLKExtractCutPieceFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The piece (its RegionId) to extract. Default 0.
  vtkSetClampMacro(Piece, int, 0, VTK_INT_MAX);
  vtkGetMacro(Piece, int);
  ///@}

  ///@{
  /// Carry the cut's point and cell data to the piece (default on).
  vtkSetMacro(PassAttributes, bool);
  vtkGetMacro(PassAttributes, bool);
  vtkBooleanMacro(PassAttributes, bool);
  ///@}

  /// Output 1: the piece's cut lines (see above).
  vtkPolyData* GetCutLinesOutput();

protected:
  vtkLKExtractCutPieceFilter();
  ~vtkLKExtractCutPieceFilter() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Piece = 0;
  bool PassAttributes = true;

private:
  vtkLKExtractCutPieceFilter(const vtkLKExtractCutPieceFilter&) = delete;
  void operator=(const vtkLKExtractCutPieceFilter&) = delete;
};

#endif
