/**
 * @class   vtkLKSymmetryPlaneFilter
 * @brief   Finds a bone's plane of symmetry (a mandible's or a skull's
 *          mid-sagittal plane) and mirrors the surface across it.
 *
 * Mirror-image planning: where one side of the jaw is deformed, resected or
 * broken, the mirror image of the other side is what the surgeon rebuilds
 * it to. The segment is moved onto it, and a reconstruction plate is bent on
 * a printed model of it before the operation.
 *
 * Method (lk::findSymmetryPlane): the surface is reflected across the plane
 * through the mean of its points normal to InitialNormal (default x, the
 * patient's left-right axis in both LPS and RAS), and that reflection is
 * registered rigidly onto the surface by iterative closest points (closest
 * points on the triangles through CGAL's AABB tree, the rigid motion by
 * Eigen's umeyama). At every iteration the points whose mirror lands
 * farthest from the bone are left out, in the share that FICP's fractional
 * RMS picks (Phillips, Liu and Tomasi 2007), at most TrimFraction: a tumour,
 * a displaced fragment or a missing part on one side (and the healthy side's
 * mirror over the gap) do not pull the plane, and a symmetric bone keeps
 * nearly every point. The reflection followed by the rigid motion is an
 * improper isometry; the plane is that of the reflection nearest it
 * (Frobenius norm): its normal is the eigenvector of the smallest eigenvalue
 * of the symmetric part of the linear map, turned to agree with
 * InitialNormal, and it passes through the mean of the midpoints between the
 * points kept and their images. A bone far from symmetric, or an
 * InitialNormal far from its plane, can end in a local minimum: the fitted
 * normal, the mean distance and the share kept tell.
 *
 * With FitPlane off, no plane is fitted: the surface is mirrored across a
 * given plane (one a surgeon set through midline landmarks), and the same
 * distances are reported.
 *
 * Input: a surface (polygons or strips, any number of pieces). Output: the
 * input mirrored across the fitted plane: points and point normals and
 * vectors reflected, each cell's points in reverse order so that its normal
 * still points out of the bone, point, cell and field data carried. Field
 * data: SymmetryPlaneOrigin and SymmetryPlaneNormal (3 values each),
 * SymmetryMeanDistance and SymmetryMaximumDistance: the mean and largest
 * distance from the input's points to the mirror image, in the input's
 * units (how far the bone is from symmetric about the plane), and
 * SymmetryKeptFraction, the share of the points the registration kept. The same
 * values are kept in the filter after an update (GetPlaneOrigin, ...).
 */
#ifndef vtkLKSymmetryPlaneFilter_h
#define vtkLKSymmetryPlaneFilter_h

#include "LatticeKitFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class LATTICEKITFILTERS_EXPORT vtkLKSymmetryPlaneFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkLKSymmetryPlaneFilter* New();
  vtkTypeMacro(vtkLKSymmetryPlaneFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The normal of the plane to start from (default 1, 0, 0); finite and not
  /// zero. Its length does not matter.
  vtkSetVector3Macro(InitialNormal, double);
  vtkGetVector3Macro(InitialNormal, double);
  ///@}

  ///@{
  /// The registration's iterations (default 200; 1 to 10,000; it stops
  /// sooner when no point moves farther than 10^-6 of the bounding box's
  /// diagonal) and the points it registers (default 20,000; 3 to 10^7; all
  /// of them when there are fewer, else as many evenly spread: a skull's
  /// 280,000 points cost 14 times the time for the same plane). The
  /// distances reported are over every point.
  vtkSetMacro(MaximumNumberOfIterations, int);
  vtkGetMacro(MaximumNumberOfIterations, int);
  vtkSetMacro(MaximumNumberOfPoints, int);
  vtkGetMacro(MaximumNumberOfPoints, int);
  ///@}

  ///@{
  /// The largest share of the points an iteration may leave out: those whose
  /// mirror image lands farthest from the bone (trimmed ICP; the share is
  /// picked at each iteration, up to this). Default 0.5; 0 (plain ICP) to 0.9.
  vtkSetMacro(TrimFraction, double);
  vtkGetMacro(TrimFraction, double);
  ///@}

  ///@{
  /// Off: no plane is fitted; the surface is mirrored across the plane
  /// through GivenPlaneOrigin with normal GivenPlaneNormal (a plane a surgeon
  /// set by landmarks), and the distances to that mirror image are
  /// reported, with KeptFraction 0. Default on.
  vtkSetMacro(FitPlane, bool);
  vtkGetMacro(FitPlane, bool);
  vtkBooleanMacro(FitPlane, bool);
  vtkSetVector3Macro(GivenPlaneOrigin, double);
  vtkGetVector3Macro(GivenPlaneOrigin, double);
  vtkSetVector3Macro(GivenPlaneNormal, double);
  vtkGetVector3Macro(GivenPlaneNormal, double);
  ///@}

  ///@{
  /// The fitted (or given) plane (a point of it and its unit normal) and the mean and
  /// largest distance from the input's points to its mirror image, after an
  /// update (zeros before, or after an error).
  vtkGetVector3Macro(PlaneOrigin, double);
  vtkGetVector3Macro(PlaneNormal, double);
  vtkGetMacro(MeanDistance, double);
  vtkGetMacro(MaximumDistance, double);
  /// The share of the points kept at the registration's last iteration.
  vtkGetMacro(KeptFraction, double);
  ///@}

protected:
  vtkLKSymmetryPlaneFilter() = default;
  ~vtkLKSymmetryPlaneFilter() override = default;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double InitialNormal[3] = { 1.0, 0.0, 0.0 };
  int MaximumNumberOfIterations = 200;
  int MaximumNumberOfPoints = 20000;
  double TrimFraction = 0.5;
  bool FitPlane = true;
  double GivenPlaneOrigin[3] = { 0.0, 0.0, 0.0 };
  double GivenPlaneNormal[3] = { 1.0, 0.0, 0.0 };
  double PlaneOrigin[3] = { 0.0, 0.0, 0.0 };
  double PlaneNormal[3] = { 0.0, 0.0, 0.0 };
  double MeanDistance = 0.0;
  double MaximumDistance = 0.0;
  double KeptFraction = 0.0;

private:
  vtkLKSymmetryPlaneFilter(const vtkLKSymmetryPlaneFilter&) = delete;
  void operator=(const vtkLKSymmetryPlaneFilter&) = delete;
};

#endif
