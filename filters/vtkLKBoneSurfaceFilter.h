/**
 * @class   vtkLKBoneSurfaceFilter
 * @brief   CT volume (or 0/1 label map) to a clean, manifold bone surface in patient space.
 *
 * The steps, each a proven VTK or CGAL piece:
 *  0. optional crop (Cropping, CropBox in patient coordinates): the voxels
 *     inside the box (vtkExtractVOI), padded by one voxel of the volume's
 *     smallest value (vtkImageConstantPad) so that the surface closes where
 *     the box cuts bone, as a saw would; the mandible below the occlusal
 *     plane, for one, where the teeth join it to the skull. Without a crop,
 *     CloseAtBorder pads the whole volume the same way, so that bone the
 *     scan's border cuts (a skull vault above the last slice) is closed
 *     there too;
 *  1. optional Gaussian smoothing of the volume (vtkImageGaussianSmooth,
 *     ImageSmoothing = standard deviation in voxels);
 *  2. optional filling of enclosed cavities (FillCavities, lk::enclosedBackground):
 *     the outer surface only;
 *  3. iso-surface by flying edges (vtkFlyingEdges3D) at IsoValue; the default,
 *     300 HU, keeps cortical and most trabecular bone;
 *  4. component selection (vtkPolyDataConnectivityFilter): all, the largest,
 *     or the one closest to SeedPoint (patient coordinates);
 *  5. placement in patient coordinates with the input's "PatientMatrix" field
 *     data (from vtkLKMedicalImageReader) or SetPatientMatrix; a mirroring
 *     matrix reverses the triangles so that they stay outward; with the
 *     reader's matrix its "SPACE" tag ("LPS", when the file gives the
 *     orientation) goes into the output's field data, where the command-line
 *     tools find it to tag the files they write as 3D Slicer does;
 *  6. repair into a manifold, consistently outward-oriented triangle mesh
 *     that CGAL accepts (vtkLKMeshRepairFilter);
 *  7. optional light smoothing (vtkWindowedSincPolyDataFilter,
 *     SmoothingIterations, pass band 0.1), which moves points only.
 *
 * Label maps: when LabelMapMode is on, or when it is AUTO (the default) and
 * the volume has integer voxels that are all 0 or 1, the iso value becomes
 * 0.5 and, unless ImageSmoothing and SmoothingIterations were set, the
 * volume is smoothed with a Gaussian of LabelMapImageSmoothing voxels (0.5)
 * and the surface with LabelMapSmoothingIterations windowed-sinc iterations
 * (20), so that it is not stair-stepped. Label picks one label of a label
 * map with several. Of the settings measured against shapes whose surface
 * is known, made into label maps on a planning CT's grid (0.98 x 0.98 x
 * 2.5 mm) and finer ones, these followed the shape most closely on average
 * in every case (a smooth mandible: 0.12-0.13 mm against 0.19-0.22 mm for a
 * Gaussian of one voxel, the default until December 2026, whose 2.5 mm
 * across the slices wore the coronoid tips 3.5 to 5.9 mm short; NOTES,
 * sessions 72 and 73); at a thick shape's worst point they can be 0.2 mm
 * farther. A Gaussian still eats away what is only a few voxels thick (a
 * printed guide's 4 mm wall on 2.5 mm slices, read back from a structure
 * set): when the (closed) surface encloses less than 80 % of the labelled
 * voxels' volume, a warning says so (ImageSmoothing 0 keeps such a label
 * whole). Steps 1 to 3 take a label map's content only (the voxels other
 * than its smallest value, and a margin of background twice the Gaussian's
 * reach and two voxels wide,
 * vtkExtractVOI): the same triangles as over the whole grid, since the
 * Gaussian renormalises its kernel at the volume's edge and sees background
 * only near the margin's edge. A mandible in a whole CT's grid is then
 * contoured in 0.07 s instead of 2 s.
 *
 * An iso value outside the volume's scalar range is an error, as is an empty
 * result.
 */
#ifndef vtkLKBoneSurfaceFilter_h
#define vtkLKBoneSurfaceFilter_h

#include "LatticeKitFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <string>

class vtkMatrix4x4;

class LATTICEKITFILTERS_EXPORT vtkLKBoneSurfaceFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkLKBoneSurfaceFilter* New();
  vtkTypeMacro(vtkLKBoneSurfaceFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ExtractionModes
  {
    ALL_COMPONENTS = 0,
    LARGEST_COMPONENT = 1,
    SEEDED_COMPONENT = 2
  };
  enum LabelMapModes
  {
    LABEL_MAP_OFF = 0,
    LABEL_MAP_ON = 1,
    LABEL_MAP_AUTO = 2
  };

  ///@{
  /// Iso value in the volume's units (HU for CT). Default 300.
  vtkSetMacro(IsoValue, double);
  vtkGetMacro(IsoValue, double);
  ///@}

  ///@{
  /// Gaussian standard deviation in voxels applied to the volume, at most 20
  /// (a kernel 121 voxels wide); 0 = none, negative (default) = automatic
  /// (LabelMapImageSmoothing for label maps, none otherwise). NaN or more
  /// than 20 is an error.
  vtkSetMacro(ImageSmoothing, double);
  vtkGetMacro(ImageSmoothing, double);
  ///@}

  ///@{
  /// Windowed-sinc smoothing iterations on the surface (pass band 0.1), at
  /// most 1000; 0 = none, negative (default) = automatic
  /// (LabelMapSmoothingIterations for label maps, none otherwise).
  vtkSetClampMacro(SmoothingIterations, int, -1, 1000);
  vtkGetMacro(SmoothingIterations, int);
  ///@}

  ///@{
  /// What the automatic ImageSmoothing and SmoothingIterations are for a
  /// label map: a Gaussian of 0.5 voxel and 20 iterations by default (see the
  /// class documentation). 1 and 0 give the surfaces made before December
  /// 2026; the planner sets them so for a session saved then. The same
  /// limits as ImageSmoothing's and SmoothingIterations'.
  vtkSetMacro(LabelMapImageSmoothing, double);
  vtkGetMacro(LabelMapImageSmoothing, double);
  vtkSetClampMacro(LabelMapSmoothingIterations, int, 0, 1000);
  vtkGetMacro(LabelMapSmoothingIterations, int);
  ///@}

  ///@{
  /// Which components to keep. Default: LARGEST_COMPONENT.
  vtkSetClampMacro(ExtractionMode, int, ALL_COMPONENTS, SEEDED_COMPONENT);
  vtkGetMacro(ExtractionMode, int);
  void SetExtractionModeToAllComponents() { this->SetExtractionMode(ALL_COMPONENTS); }
  void SetExtractionModeToLargestComponent() { this->SetExtractionMode(LARGEST_COMPONENT); }
  void SetExtractionModeToSeededComponent() { this->SetExtractionMode(SEEDED_COMPONENT); }
  ///@}

  ///@{
  /// Seed for SEEDED_COMPONENT, in patient coordinates (mm).
  vtkSetVector3Macro(SeedPoint, double);
  vtkGetVector3Macro(SeedPoint, double);
  ///@}

  ///@{
  /// Treat the input as a 0/1 label map (see the class documentation).
  vtkSetClampMacro(LabelMapMode, int, LABEL_MAP_OFF, LABEL_MAP_AUTO);
  vtkGetMacro(LabelMapMode, int);
  ///@}

  ///@{
  /// One label of a label map with several (a segmentation of 3D Slicer or
  /// another tool: mandible 1, maxilla 2, ...): when positive, the voxels
  /// holding it become 1 and every other voxel 0, and the volume is taken as
  /// a 0/1 label map (iso 0.5, one voxel of Gaussian unless ImageSmoothing
  /// says otherwise). 0 (default): off. A label no voxel holds, or a volume
  /// that is not of integers, is an error that lists the labels there are.
  vtkSetClampMacro(Label, int, 0, VTK_INT_MAX);
  vtkGetMacro(Label, int);
  ///@}

  ///@{
  /// One segment of a 3D Slicer segmentation by its name (the reader's
  /// "SegmentNames", "SegmentLabelValues" and "SegmentLayers" field data,
  /// from a .seg.nrrd): when set, it gives Label (and the layer). Matched as
  /// written, else ignoring case; a name the segmentation does not have is an
  /// error that lists its segments. Default: none.
  ///
  /// A segmentation whose segments overlap has several layers (a component
  /// each), and each layer numbers its segments from 1: one segment must be
  /// chosen, by its name or by a label value that only one segment has.
  vtkSetStringMacro(LabelName);
  vtkGetStringMacro(LabelName);
  ///@}

  ///@{
  /// Fill enclosed cavities before the iso-surface (default off): voxels on
  /// the low side of the iso value that cannot reach the volume's border,
  /// in 3D or within their own slice (the k axis, axial for CT), take the
  /// volume's largest value. The surface is then the outer one: at the skin's
  /// value (about -400 HU) the sinuses, the airway and the mouth no longer
  /// join the skin (on the bundled head: genus 253 to 11); at a bone value,
  /// the marrow and the skull's inside are filled.
  vtkSetMacro(FillCavities, bool);
  vtkGetMacro(FillCavities, bool);
  vtkBooleanMacro(FillCavities, bool);
  ///@}
  ///@{
  /// Crop the volume to CropBox first (default off). The box is
  /// (xmin, xmax, ymin, ymax, zmin, zmax) in patient coordinates (mm), those
  /// of the surface and the seed; its corners go to the volume's voxels
  /// through the inverse of the patient matrix, and the voxels that hold
  /// them all are kept. A box that misses the volume, or whose min is not
  /// below its max, is an error.
  vtkSetMacro(Cropping, bool);
  vtkGetMacro(Cropping, bool);
  vtkBooleanMacro(Cropping, bool);
  vtkSetVector6Macro(CropBox, double);
  vtkGetVector6Macro(CropBox, double);
  ///@}

  ///@{
  /// Close the surface where the volume's border cuts bone (default off):
  /// the volume is padded by one voxel of its smallest value on every side,
  /// as a crop box is. A scan that ends inside the bone (a skull vault above
  /// the last slice, a spine below the first) otherwise gives an open
  /// surface there, which no closed line around part of it can cut in two
  /// and no printer fills. A crop is always closed, with or without it.
  vtkSetMacro(CloseAtBorder, bool);
  vtkGetMacro(CloseAtBorder, bool);
  vtkBooleanMacro(CloseAtBorder, bool);
  ///@}

  ///@{
  /// Repair into a CGAL-valid manifold mesh (default on).
  vtkSetMacro(Repair, bool);
  vtkGetMacro(Repair, bool);
  vtkBooleanMacro(Repair, bool);
  ///@}

  ///@{
  /// Data coordinates to patient coordinates. When not set, the input's
  /// "PatientMatrix" field data is used, and failing that the identity.
  void SetPatientMatrix(vtkMatrix4x4* m);
  vtkMatrix4x4* GetPatientMatrix() { return this->PatientMatrix; }
  ///@}

  /// Whether the last input was treated as a label map.
  bool GetTreatedAsLabelMap() const { return this->TreatedAsLabelMap; }
  /// The iso value the last update used (0.5 for label maps).
  double GetEffectiveIsoValue() const { return this->EffectiveIsoValue; }
  /// The Gaussian (voxels) and the surface's smoothing iterations the last
  /// update used, the automatic ones resolved.
  double GetEffectiveImageSmoothing() const { return this->EffectiveImageSmoothing; }
  int GetEffectiveSmoothingIterations() const { return this->EffectiveSmoothingIterations; }
  /// The label the last update took (Label, or LabelName's value; 0: none).
  int GetEffectiveLabel() const { return this->EffectiveLabel; }
  /// The name of the segment the last update took (a segmentation's, by
  /// LabelName or by Label), or "".
  const char* GetEffectiveSegmentName() const { return this->EffectiveSegmentName.c_str(); }

protected:
  vtkLKBoneSurfaceFilter();
  ~vtkLKBoneSurfaceFilter() override;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  vtkMTimeType GetMTime() override;

  double IsoValue = 300.0;
  double ImageSmoothing = -1.0;
  int SmoothingIterations = -1;
  double LabelMapImageSmoothing = 0.5;
  int LabelMapSmoothingIterations = 20;
  int ExtractionMode = LARGEST_COMPONENT;
  double SeedPoint[3] = { 0.0, 0.0, 0.0 };
  int LabelMapMode = LABEL_MAP_AUTO;
  int Label = 0;
  char* LabelName = nullptr;
  bool Repair = true;
  bool FillCavities = false;
  bool Cropping = false;
  bool CloseAtBorder = false;
  double CropBox[6] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 };
  vtkMatrix4x4* PatientMatrix = nullptr;
  bool TreatedAsLabelMap = false;
  int EffectiveLabel = 0;
  std::string EffectiveSegmentName;
  double EffectiveIsoValue = 300.0;
  double EffectiveImageSmoothing = 0.0;
  int EffectiveSmoothingIterations = 0;

private:
  vtkLKBoneSurfaceFilter(const vtkLKBoneSurfaceFilter&) = delete;
  void operator=(const vtkLKBoneSurfaceFilter&) = delete;
};

#endif
