/**
 * @class   vtkLKClosedLineCutFilter
 * @brief   Cuts a surface (or a lattice) along closed lines into pieces,
 *          optionally capped so that each piece is watertight (seed 004, 3.2).
 *
 * Input 0: a manifold polygon mesh (triangles, or a lattice's polygons); its
 * line cells are ignored as geometry. Input 1 (optional, SetLinesConnection /
 * SetLinesData): the closed lines, as polylines or as separate segments along
 * mesh edges, whose points name mesh points (point data "MeshPointId", or
 * coordinates equal to mesh points; with ids, a point far from the point its
 * id names is warned of, as lines made on another mesh). Without input 1 the
 * line cells of input 0 are the lines: a fitted lattice (vtkLKLatticeFitFilter)
 * carries its feature edges as line cells, so "fit, then cut" is one pipeline.
 * The lines must form closed loops: every vertex on them joins exactly two
 * line edges.
 *
 * Output: all pieces in one polydata, the loop vertices duplicated so each
 * piece has its own; cell data "RegionId" (the piece), "InputCellId" (-1 on
 * caps), "Cap" (1 on cap triangles); point data "InputPointId" (-1 on cap
 * points and the points of inner-wall lines); the input's point and cell
 * data, carried from those ids (the arrays' null value on cap points and cap
 * faces; normals are left out, since a cap's would be null; the input's field
 * data passes too); field data "Pieces",
 * "InnerWallLines" (see CutInnerWalls) and "LinesInOnePiece" (lines that
 * separate nothing, because the bone joins around them: each stays a slit,
 * its caps back to back, with a warning that gives its place). Their cut borders coincide exactly. With
 * Capping, each loop is closed by one hole-filling surface (CGAL triangulate
 * and refine; flat for a near-planar loop) shared, reversed, by the two pieces beside
 * it: both pieces are closed and fit each other (see MeshCut.h). Near-planar
 * lines nested in one plane (around the outer and the inner wall of a hollow
 * bone) share one flat cap with holes (an annulus). A cap that crosses its
 * piece's surface (a line far from planar) or another cap is reported: a
 * warning, and field data "CapCrossings" (per piece, the pairs of
 * intersecting triangles of which one is a cap triangle; 0 when clean) and
 * "CapCrossingDepth" (per piece, the deepest overlap of such a pair: how far
 * each triangle reaches through the other's plane on its shallower side, the
 * smaller of the two; micrometres where triangles graze beside a line). A
 * line along mesh edges that detours around a stretch of bone the cap covers
 * too leaves a pocket between the two, taken out, or a cap edge on a bone
 * edge, split (MeshCut.h), so the piece stays a manifold solid; field data
 * "CapNonManifoldEdges" (per piece; 0 when manifold) and a warning say so if
 * an edge at a cap still has more than two faces.
 *
 * Bad input (an open line, lines crossing, a loop that crosses itself, loops
 * that do not separate the mesh, points that are not mesh points) gives a
 * VTK error and an empty output.
 */
#ifndef vtkLKClosedLineCutFilter_h
#define vtkLKClosedLineCutFilter_h

#include "LatticeKitFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class LATTICEKITFILTERS_EXPORT vtkLKClosedLineCutFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkLKClosedLineCutFilter* New();
  vtkTypeMacro(vtkLKClosedLineCutFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  void SetLinesConnection(vtkAlgorithmOutput* output);
  void SetLinesData(vtkPolyData* lines);

  ///@{
  /// Close every piece with the loop's shared cap (default off).
  vtkSetMacro(Capping, bool);
  vtkGetMacro(Capping, bool);
  vtkBooleanMacro(Capping, bool);
  ///@}

  ///@{
  /// Where the lines do not separate the surface because it is hollow (a
  /// marrow cavity or canal inside a bone, joined to the outside), also cut
  /// the inner walls where a near-planar line's plane meets them inside the
  /// line, as a saw does; with Capping, the inner and outer lines share one
  /// flat cap, an annulus (default on; see MeshCut.h). With Capping, the same
  /// is tried where the lines separate but a cap crosses the surface (a canal
  /// open at one end only, or a dip inside the line, reaching through the
  /// plane) or a piece gets no cap (a closed cavity): each part beyond the
  /// plane joins the piece on its side, and the result is kept if its caps
  /// cross less, or as much with fewer pieces. Off: lines that do not separate are
  /// refused, with the number of handles that join their sides.
  vtkSetMacro(CutInnerWalls, bool);
  vtkGetMacro(CutInnerWalls, bool);
  vtkBooleanMacro(CutInnerWalls, bool);
  ///@}

  /// Pieces of the last update.
  int GetNumberOfPieces() const { return this->NumberOfPieces; }
  /// Lines the last update added on inner walls (also field data "InnerWallLines").
  int GetNumberOfInnerWallLines() const { return this->NumberOfInnerWallLines; }

protected:
  vtkLKClosedLineCutFilter();
  ~vtkLKClosedLineCutFilter() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  bool Capping = false;
  bool CutInnerWalls = true;
  int NumberOfPieces = 0;
  int NumberOfInnerWallLines = 0;

private:
  vtkLKClosedLineCutFilter(const vtkLKClosedLineCutFilter&) = delete;
  void operator=(const vtkLKClosedLineCutFilter&) = delete;
};

#endif
