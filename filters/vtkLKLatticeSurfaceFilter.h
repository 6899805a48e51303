/**
 * @class   vtkLKLatticeSurfaceFilter
 * @brief   The smooth lattice surface of a polygonal control mesh.
 *
 * Input: a lattice, a polygonal mesh of triangles, quads and n-gons, closed or
 * open, manifold and consistently oriented. Output 0: the tessellated smooth
 * surface (seed 004, section 2.1): one Doo-Sabin step, a cubic Bezier curve
 * per lattice edge, a bicubic Gregory patch per quad and n quad patches per
 * other n-gon, joined with tangent-plane (G1) continuity. See
 * core/include/latticekit/LatticeSurface.h for the construction and the
 * choices made where the paper's formulas lost their fractions.
 *
 * Tessellation: each quad's patch becomes a Resolution x Resolution grid
 * (Resolution is rounded up to even), each patch of a split face a
 * Resolution/2 grid, so neighbouring patches sample their shared curves at
 * the same parameters; each such sample is named by its curve and step and
 * becomes one point, so the output is a watertight triangle mesh, built
 * deterministically. At a crease (see below) the shared points keep the
 * normal of one side, which shades a band along it; with SplitCreases each
 * side keeps its own points and normals instead (crisp edges, as
 * vtkPolyDataNormals's splitting gives, and the mesh is then open along
 * the creases). Point data "Normals" come from the patch derivatives, not
 * from the triangles; cell data "LatticeFaceId" and "PatchId" name the
 * lattice face and the patch of each triangle. Field data "DisplayPolygons"
 * counts the triangles (the paper's display polygons), "Patches" the patches.
 *
 * Output 1 (control net, for inspection): the Bezier control polygon of every
 * lattice edge curve as a polyline, and the eight interior Gregory points of
 * every patch as vertices.
 *
 * Rounding weights (XVL's lattice weights; see LatticeSurface.h for what
 * they do): point data "RoundingWeight" in [0, 1] gives vertex weights (0
 * makes the surface pass through the lattice vertex); line cells of the
 * input lying on lattice edges mark those edges, with cell data
 * "RoundingWeight" as their weight (0 when the array is missing): weight 0
 * makes the edge a sharp crease, and a vertex on three or more creases a
 * sharp corner; weights in (0, 1) keep the surface G1 but round the edge
 * more tightly as they fall.
 *
 * After an update, EvaluatePatch gives position, unit normal and first
 * derivatives at (patch, u, v).
 *
 * Closest points: FindClosestPoint (an AABB tree over a fine tessellation,
 * then Gauss-Newton and a pattern search on the exact patch).
 */
#ifndef vtkLKLatticeSurfaceFilter_h
#define vtkLKLatticeSurfaceFilter_h

#include "LatticeKitFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <memory>

class LATTICEKITFILTERS_EXPORT vtkLKLatticeSurfaceFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkLKLatticeSurfaceFilter* New();
  vtkTypeMacro(vtkLKLatticeSurfaceFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Segments per side of a quad's patch (default 8, rounded up to even, 2 to 256).
  vtkSetClampMacro(Resolution, int, 2, 256);
  vtkGetMacro(Resolution, int);
  ///@}

  ///@{
  /// When positive, the tessellation resolution is chosen instead of taken
  /// from Resolution: the smallest even one (up to 256) at which every grid
  /// cell's centre lies within this distance of the mean of its four corners
  /// (a chordal deviation estimate), one resolution for the whole surface so
  /// that it stays watertight. Default 0 (use Resolution).
  vtkSetClampMacro(ChordalTolerance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(ChordalTolerance, double);
  ///@}

  ///@{
  /// Split the tessellation along creases (edges of weight 0 between two
  /// faces): each side gets its own points there, with its own normals, and
  /// a vertex on creases one point per sector of faces between them. Off by
  /// default: one watertight mesh, whose points on a crease carry one side's
  /// normal.
  vtkSetMacro(SplitCreases, bool);
  vtkGetMacro(SplitCreases, bool);
  vtkBooleanMacro(SplitCreases, bool);
  ///@}

  /// The resolution the last update used.
  int GetEffectiveResolution() const { return this->EffectiveResolution; }

  /// The control net output (port 1).
  vtkPolyData* GetControlNetOutput();

  /// Number of Gregory patches of the last update.
  vtkIdType GetNumberOfPatches() const;

  /// Position, unit normal and derivatives of a patch at (u, v) in [0, 1]^2,
  /// after an update. Returns false for a patch id out of range.
  bool EvaluatePatch(vtkIdType patch, double u, double v, double position[3], double normal[3],
    double du[3], double dv[3]);
  /// Position and unit normal only.
  bool EvaluatePatch(vtkIdType patch, double u, double v, double position[3], double normal[3]);

  /// Closest point of the surface to `query` (after an update): writes the
  /// point and returns the distance, or -1 without a surface. The patch and
  /// its (u, v) are given by GetLastClosestPatch / GetLastClosestUV.
  double FindClosestPoint(const double query[3], double closest[3]);
  vtkIdType GetLastClosestPatch() const { return this->LastClosestPatch; }
  void GetLastClosestUV(double uv[2]) const
  {
    uv[0] = this->LastClosestUV[0];
    uv[1] = this->LastClosestUV[1];
  }

protected:
  vtkLKLatticeSurfaceFilter();
  ~vtkLKLatticeSurfaceFilter() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Resolution = 8;
  double ChordalTolerance = 0.0;
  bool SplitCreases = false;
  int EffectiveResolution = 0;
  vtkIdType LastClosestPatch = -1;
  double LastClosestUV[2] = { 0.0, 0.0 };

private:
  vtkLKLatticeSurfaceFilter(const vtkLKLatticeSurfaceFilter&) = delete;
  void operator=(const vtkLKLatticeSurfaceFilter&) = delete;
  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
