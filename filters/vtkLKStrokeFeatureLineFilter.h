/**
 * @class   vtkLKStrokeFeatureLineFilter
 * @brief   Turns a pen stroke on a triangle mesh into a feature line (seed
 *          004, section 3.1): paint, nearest edges, snap or split.
 *
 * Input 0: a triangle mesh. Input 1 (SetStrokeConnection / SetStrokeData):
 * the stroke as world points on or near the surface (the points of the
 * first polyline, or all points in order when there is no line cell).
 * See core/include/latticekit/StrokeFeatureLine.h for the modes:
 * PAINT (every edge of the faces within BrushRadius of the stroke),
 * NEAREST_EDGES (the edge path through the vertices nearest the stroke,
 * without self-intersection), SNAP (that path with its vertices moved onto
 * the stroke, connectivity unchanged; a vertex whose move would fold a
 * triangle around it, turning it by more than 60 degrees or leaving it less
 * than 1 % of its area, stops short, with a warning and its distance left in
 * point data "StrokeGap" of output 1) and SPLIT (new vertices where the
 * stroke crosses edges and at its ends, faces split so that new edges follow
 * the stroke; the mesh stays a manifold triangle mesh; points far apart are joined
 * across the faces, walked in parts where one plane does not follow the
 * surface between them, and a segment that cannot be followed is an error
 * that says to draw it with its points closer together). A stroke whose ends
 * are within CloseTolerance gives a closed line.
 *
 * Line cells on input 0 are earlier feature lines (output 0 of another
 * stroke filter, so strokes chain): they are passed to output 0, and where a
 * SPLIT stroke cuts one of their edges the new vertex on it joins them
 * (CarryLine does the same for a line kept apart, such as output 1).
 *
 * Output 0: the mesh (vertices moved in SNAP mode, faces split in SPLIT mode), plus
 * the input's line cells and one line cell per new feature edge (cell data
 * "FeatureEdge" 1 on the lines, 0 on the triangles). The input's point data
 * is carried (interpolated at a split's new points, in the triangle they lie
 * in; id arrays then left out, as VTK's interpolating filters leave them),
 * and its cell data on every triangle from the input triangle it is or lies
 * in (the null value on the line cells); normals only in PAINT and
 * NEAREST_EDGES, which leave the surface as it was. Output 1: the feature line as a polyline (NEAREST_EDGES, SNAP;
 * closed lines repeat their first point) or the feature edges as segments
 * (PAINT), with point data "MeshPointId": the form vtkLKLatticeFitFilter
 * (feature lines) and vtkLKClosedLineCutFilter (cut lines) take. Field data
 * "Closed" (1 or 0).
 *
 * Screen strokes: with a Camera and a ViewportSize set, the stroke's points
 * are display coordinates (x, y in pixels from the viewport's lower left; z
 * is ignored), as the interactor reports mouse positions. Each is picked onto
 * the nearest visible surface along the ray from the eye through that pixel
 * (the paper's picking, section 3.1), on an OBB tree of the mesh; pixels
 * whose ray misses the surface are skipped. The picked world points then go
 * through the chosen mode as a world-space stroke would. Without a camera
 * (the default) the points are world points.
 *
 * Bad input (a stroke of fewer than two points, non-finite points, a stroke
 * that misses the surface, a mesh that is not triangles) gives a VTK error
 * and empty outputs.
 */
#ifndef vtkLKStrokeFeatureLineFilter_h
#define vtkLKStrokeFeatureLineFilter_h

#include "LatticeKitFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class vtkCamera;

class LATTICEKITFILTERS_EXPORT vtkLKStrokeFeatureLineFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkLKStrokeFeatureLineFilter* New();
  vtkTypeMacro(vtkLKStrokeFeatureLineFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Modes
  {
    PAINT = 0,
    NEAREST_EDGES = 1,
    SNAP = 2,
    SPLIT = 3
  };

  void SetStrokeConnection(vtkAlgorithmOutput* output);
  void SetStrokeData(vtkPolyData* stroke);

  ///@{
  vtkSetClampMacro(Mode, int, PAINT, SPLIT);
  vtkGetMacro(Mode, int);
  void SetModeToPaint() { this->SetMode(PAINT); }
  void SetModeToNearestEdges() { this->SetMode(NEAREST_EDGES); }
  void SetModeToSnap() { this->SetMode(SNAP); }
  void SetModeToSplit() { this->SetMode(SPLIT); }
  ///@}

  ///@{
  /// Lengths in model units; 0 (default) picks one from the mean edge length
  /// (brush: half of it; close tolerance: twice it).
  vtkSetClampMacro(BrushRadius, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(BrushRadius, double);
  vtkSetClampMacro(CloseTolerance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(CloseTolerance, double);
  ///@}

  /// The close tolerance a stroke on `surface` gets when CloseTolerance is 0
  /// (twice its mean edge length); 0 for a surface the filter would refuse
  /// (no triangles, other polygons).
  static double DefaultCloseTolerance(vtkPolyData* surface);

  ///@{
  /// Screen strokes (see above): the camera that showed the mesh and the
  /// viewport's size in pixels. SetCamera(nullptr) goes back to world points.
  void SetCamera(vtkCamera* camera);
  vtkGetObjectMacro(Camera, vtkCamera);
  vtkSetVector2Macro(ViewportSize, int);
  vtkGetVector2Macro(ViewportSize, int);
  ///@}

  /// The stroke as picked on the surface (world points) in the last update:
  /// the input stroke itself for world strokes.
  vtkPolyData* GetPickedStroke();

  /// Output 1: the feature line with MeshPointId.
  vtkPolyData* GetFeatureLineOutput();

  /// An earlier feature line on this filter's input (polylines with point
  /// data MeshPointId, as output 1 of an earlier stroke gives it), carried
  /// onto output 0 of the last update: SPLIT cuts the mesh edges its stroke
  /// crosses, and an edge of the earlier line it cut is replaced by the new
  /// vertices on it (lk::carryLines). `carried` gets the line with
  /// MeshPointId on output 0's points and `line`'s field data. Returns 0,
  /// with an error, when `line` has no MeshPointId or names a point the
  /// input did not have.
  int CarryLine(vtkPolyData* line, vtkPolyData* carried);

protected:
  vtkLKStrokeFeatureLineFilter();
  ~vtkLKStrokeFeatureLineFilter() override;
  vtkMTimeType GetMTime() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Mode = NEAREST_EDGES;
  double BrushRadius = 0.0;
  double CloseTolerance = 0.0;
  vtkCamera* Camera = nullptr;
  int ViewportSize[2] = { 0, 0 };
  vtkPolyData* PickedStroke = nullptr;
  vtkIdType InputPoints = 0; ///< of the last update's input, for CarryLine

private:
  vtkLKStrokeFeatureLineFilter(const vtkLKStrokeFeatureLineFilter&) = delete;
  void operator=(const vtkLKStrokeFeatureLineFilter&) = delete;
};

#endif
