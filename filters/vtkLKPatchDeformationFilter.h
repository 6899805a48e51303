/**
 * @class   vtkLKPatchDeformationFilter
 * @brief   Deformation of adaptively refined micro planar patches (seed 002,
 *          Futagami, Mizuguchi and Morita), for scripted and interactive use.
 *
 * Input: a manifold triangle mesh (open or closed; a planar patch in the
 * paper). The deformations added to the filter are applied in order to a
 * mesh that refines itself where they need it: triangles split 1-to-4 at
 * their edge midpoints, neighbours of split triangles become transition
 * triangles (output as two triangles), and the output is conforming at
 * every moment (see core/include/latticekit/AdaptivePatchMesh.h).
 * - functional (eq. 1): vertices within D of the centre move by
 *   k exp(-a d^2) along the original surface normal;
 * - range: vertices inside an axis-aligned box move by one vector;
 * - smoothing (eq. 2): inside a ball, each displacement becomes the mean of
 *   the vertex's and its neighbours' displacements, `iterations` times.
 * MaxLevel bounds the depth (default 4). Tolerance is the edge bending that
 * triggers a split (a length; 0, the default, means 0.1 % of the input's
 * bounding-box diagonal).
 *
 * Output: the refined, deformed triangles. Point data "Displacement" (from
 * the original surface) and "BaseNormals" (original normals); cell data
 * "Level" (refinement depth of each triangle); field data "SelfCrossings"
 * and "SelfCrossingDepth" (CheckCrossings). The input's point data is
 * carried, interpolated at new midpoints as VTK's subdivision filters do,
 * and its cell data copied to every triangle cut from an input triangle;
 * normals are left out, since the deformed surface's differ.
 *
 * Interactive use. The filter keeps the refined mesh between updates, as
 * the state after all its deformations and after all but the last. While
 * the input, MaxLevel and Tolerance are unchanged, an update whose list
 * starts with one of those two lists applies only the rest. So appending a
 * deformation (a smoothing brush dab), or replacing the last one
 * (RemoveLastDeformation then Add..., a drag that changes k every mouse
 * move), costs one deformation, not the whole list; removing the last (an
 * undo) costs a copy. The result is the same, to the bit, as a new filter
 * with the same list applied from scratch (tested), so a recorded list
 * replays what the user saw.
 */
#ifndef vtkLKPatchDeformationFilter_h
#define vtkLKPatchDeformationFilter_h

#include "LatticeKitFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <array>
#include <vector>

class LATTICEKITFILTERS_EXPORT vtkLKPatchDeformationFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkLKPatchDeformationFilter* New();
  vtkTypeMacro(vtkLKPatchDeformationFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Eq. 1 around (x, y, z).
  void AddFunctionalDeformation(double x, double y, double z, double k, double a, double D);
  /// Vertices in [xmin, xmax] x [ymin, ymax] x [zmin, zmax] move by (dx, dy, dz).
  void AddRangeDeformation(double xmin, double xmax, double ymin, double ymax, double zmin, double zmax,
    double dx, double dy, double dz);
  /// Eq. 2 inside the ball ((x, y, z), D), iterations times (0 to 10,000).
  void AddSmoothingDeformation(double x, double y, double z, double D, int iterations);
  void RemoveAllDeformations();
  /// Drops the last deformation added (nothing if there is none).
  void RemoveLastDeformation();
  /// Drops deformation `index` (0 is the first added) and keeps the others
  /// in order: the next update applies them again from the input (a bump
  /// taken back from under the ones made after it). An index out of range
  /// is an error, and nothing changes.
  void RemoveDeformation(int index);
  int GetNumberOfDeformations() const { return static_cast<int>(this->Deformations.size()); }

  ///@{
  /// Refinement depth bound, 0 to 12 (default 4).
  vtkSetClampMacro(MaxLevel, int, 0, 12);
  vtkGetMacro(MaxLevel, int);
  ///@}

  ///@{
  /// Edge bending that triggers a split; 0 = 0.1 % of the bounding-box diagonal.
  vtkSetMacro(Tolerance, double);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /// Whether to look for places where the deformed surface passes through
  /// itself (default on): a bump or box pushed deeper than the bone is
  /// thick, or inward sharper than its curvature. The pairs of crossing
  /// faces with at least one moved go to field data "SelfCrossings" (their
  /// count) and "SelfCrossingDepth" (how far the deepest pair reaches
  /// through each other, in mesh units), with a warning when there are any:
  /// the output is then no valid solid. When there are, "SelfCrossingsBefore"
  /// counts the input's own crossing pairs near the moved faces (a cut piece
  /// whose cap crosses the bone): the deformation did not make those (0 when
  /// the output has none). Off, neither array is written (an
  /// interactive drag can turn it off until the mouse is released).
  vtkSetMacro(CheckCrossings, bool);
  vtkGetMacro(CheckCrossings, bool);
  vtkBooleanMacro(CheckCrossings, bool);
  ///@}

protected:
  vtkLKPatchDeformationFilter();
  ~vtkLKPatchDeformationFilter() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  struct Deformation
  {
    enum Kind
    {
      Functional, ///< p: x, y, z, k, a, D
      Range,      ///< p: xmin, xmax, ymin, ymax, zmin, zmax, dx, dy, dz
      Smoothing   ///< p: x, y, z, D, iterations
    };
    Kind kind;
    std::array<double, 9> p;
    bool operator==(const Deformation& o) const { return kind == o.kind && p == o.p; }
  };
  std::vector<Deformation> Deformations;
  int MaxLevel = 4;
  double Tolerance = 0.0;
  bool CheckCrossings = true;

private:
  class vtkInternals;
  vtkInternals* Internals;
  vtkLKPatchDeformationFilter(const vtkLKPatchDeformationFilter&) = delete;
  void operator=(const vtkLKPatchDeformationFilter&) = delete;
};

#endif
