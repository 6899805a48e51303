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
 * deterministically. (At a sharp crease the shared points keep the normal
 * of one side; run vtkPolyDataNormals with splitting for crisp shading.) Point data "Normals" come from the patch derivatives, not
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
 * sharp corner. Edge weights act as 0 or 1 for now.
 *
 * After an update, EvaluatePatch gives position, unit normal and first
 * derivatives at (patch, u, v).
 *
 * Not yet: a chordal-tolerance tessellation, closest-point queries.
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

protected:
  vtkLKLatticeSurfaceFilter();
  ~vtkLKLatticeSurfaceFilter() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Resolution = 8;

private:
  vtkLKLatticeSurfaceFilter(const vtkLKLatticeSurfaceFilter&) = delete;
  void operator=(const vtkLKLatticeSurfaceFilter&) = delete;
  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
