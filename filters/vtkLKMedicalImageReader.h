/**
 * @class   vtkLKMedicalImageReader
 * @brief   One front end for CT volumes: DICOM series folders, NRRD, MetaImage, NIfTI.
 *
 * FileName may be a folder (DICOM series), a DICOM file (its folder is scanned
 * and the series holding the file is read; an RT structure set, see below),
 * or a .nrrd/.nhdr, .mha/.mhd, .nii/.nii.gz file.
 *
 * The output is a vtkImageData with origin (0,0,0) and the voxel spacing in
 * millimetres; GetPatientMatrix() maps its data coordinates to patient
 * coordinates in the DICOM convention (LPS: +x left, +y posterior, +z
 * superior). The matrix is also stored in the output's field data as
 * "PatientMatrix" (16 values, row-major), which vtkLKBoneSurfaceFilter uses to
 * place the surface in patient space.
 *
 * DICOM (through vtkDICOM): the folder is scanned with vtkDICOMDirectory;
 * vtkDICOMReader sorts the slices and applies rescale slope and intercept. If
 * the folder holds several series, the one with the most images is read
 * (SeriesIndex selects another: series are numbered largest first) and a
 * warning names the others. The geometry comes from every slice's own
 * ImagePositionPatient: a gantry-tilted series (slices sheared along the
 * stacking direction) and variable slice spacing are resampled (bilinear in
 * plane, linear between slices) onto a regular grid in the slice frame that
 * covers every slice's footprint, whose z spacing is SliceSpacing, or, when
 * SliceSpacing is 0, the largest spacing not above the smallest slice gap that
 * puts grid slices exactly on the first and last slices.
 * The DICOM output is float.
 *
 * NRRD: the "space directions", "space origin" and "space" fields of the
 * header give the matrix (RAS spaces are converted to LPS). MetaImage:
 * "TransformMatrix" (one axis direction after another) and "Offset" (LPS, as
 * ITK writes them). NIfTI: the qform (or sform when qform_code is 0), from RAS
 * to LPS; a file with neither has no defined orientation, so its data
 * coordinates are kept (with a warning); scl_slope and scl_inter calibrate
 * the values.
 *
 * A segmentation of 3D Slicer (.seg.nrrd) names its segments in the header
 * ("Segment0_Name:=mandible", "Segment0_LabelValue:=1", "Segment0_Layer:=0"):
 * the output's field data then holds "SegmentNames" (strings),
 * "SegmentLabelValues" and "SegmentLayers" (ints), which
 * vtkLKBoneSurfaceFilter's Label and LabelName look up.
 *
 * A DICOM RT structure set (RTSTRUCT: FileName is its file), as
 * radiotherapy planning systems export the organs they contour (the
 * mandible among them), becomes a label volume: each ROI's closed planar
 * contours are filled slice by slice (a voxel is the ROI's when its centre
 * lies inside; a contour inside another is a hole), each ROI a segment named
 * by its ROIName with its ROINumber as label, in field data as a
 * .seg.nrrd's. The grid is that of the CT the structure set references
 * when that series lies in the same folder (its pixel lattice, and its
 * slices when the contours lie on them), otherwise the contours' own: 1 mm
 * pixels (or the slice gap, when finer), slices on the contours' planes
 * spaced by the smallest gap between them, with a warning. Slices an ROI skips between two of its contours (it was
 * contoured every other slice) are interpolated from the shapes on either
 * side, across gaps of up to twice its usual contour spacing. ROIs without
 * closed contours (points, open lines), planes moved onto the grid and
 * slices skipped are warned of. A folder holding a
 * CT and its structure set reads the CT: give the structure set's file.
 *
 * The output has one scalar component, except for a segmentation whose
 * segments overlap: 3D Slicer stores it in layers, each a label map, and the
 * output has a component per layer (vtkLKBoneSurfaceFilter takes one segment
 * of it).
 */
#ifndef vtkLKMedicalImageReader_h
#define vtkLKMedicalImageReader_h

#include "LatticeKitFiltersModule.h"
#include "vtkImageAlgorithm.h"

#include <string>
#include <vector>

class vtkImageData;
class vtkMatrix4x4;

class LATTICEKITFILTERS_EXPORT vtkLKMedicalImageReader : public vtkImageAlgorithm
{
public:
  static vtkLKMedicalImageReader* New();
  vtkTypeMacro(vtkLKMedicalImageReader, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// A DICOM folder or file, or an NRRD, MetaImage or NIfTI file.
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /// DICOM: which series to read when a folder holds several (numbered by
  /// size, largest first); -1 (default) reads the largest.
  vtkSetMacro(SeriesIndex, int);
  vtkGetMacro(SeriesIndex, int);
  ///@}

  ///@{
  /// DICOM: spacing of the resampled slices in mm; 0 (default) chooses it
  /// from the smallest gap between consecutive slices (see above).
  vtkSetClampMacro(SliceSpacing, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(SliceSpacing, double);
  ///@}

  /// Data coordinates to patient (LPS, mm). Valid after an update.
  vtkMatrix4x4* GetPatientMatrix() { return this->PatientMatrix; }

  /// Whether the file says how its axes lie in the patient (after an update):
  /// true for DICOM, MetaImage, NRRD with "space" and "space directions",
  /// NIfTI with a qform or sform. Then the output's field data also holds
  /// "SPACE" = "LPS" (3D Slicer's tag for a coordinate system), which
  /// vtkLKBoneSurfaceFilter passes on to its surface; otherwise the patient
  /// matrix only scales (and shifts) the data coordinates.
  bool GetOrientationKnown() const { return this->OrientationKnown; }
  /// "DICOM", "DICOM SEG", "DICOM RTSTRUCT", "NRRD", "MetaImage" or "NIfTI"
  /// after an update.
  const char* GetFileFormat() { return this->FileFormat.c_str(); }

  /// After an update, a file of the DICOM image series the volume belongs
  /// to: the series read (FileFormat "DICOM"), or the CT an RT structure set
  /// or a DICOM SEG was drawn on when that CT lies in the same folder or in a
  /// folder beside it (a study exported one series to a folder, as TCIA and
  /// PACS exports lie); empty otherwise. vtkLKStructureSetWriter's ReferenceFileName takes it, so
  /// that what is made from the volume goes back to the same patient, study
  /// and slices.
  const char* GetReferenceImageFileName() { return this->ReferenceImageFileName.c_str(); }

  ///@{
  /// A segmentation's segments, after an update: a 3D Slicer .seg.nrrd's, a
  /// DICOM SEG's, an RT structure set's ROIs (none for a CT or a plain label
  /// map). Each has a name, a label value and a layer (the output's component
  /// that holds it); out of range, a name of nullptr, a value of 0 and a
  /// layer of -1. The output's field data holds the same ("SegmentNames",
  /// "SegmentLabelValues", "SegmentLayers"), which vtkLKBoneSurfaceFilter's
  /// LabelName looks up.
  int GetNumberOfSegments() const;
  const char* GetSegmentName(int i) const;
  int GetSegmentLabelValue(int i) const;
  int GetSegmentLayer(int i) const;
  ///@}

  ///@{
  /// DICOM only, after an update: the number of series in the folder, the
  /// gantry tilt in degrees, the smallest and largest slice gaps in mm, and
  /// the number of slices read.
  int GetNumberOfSeries() const { return this->NumberOfSeries; }
  double GetGantryTilt() const { return this->GantryTilt; }
  double GetMinimumSliceGap() const { return this->MinimumSliceGap; }
  double GetMaximumSliceGap() const { return this->MaximumSliceGap; }
  int GetNumberOfInputSlices() const { return this->NumberOfInputSlices; }
  ///@}

  ///@{
  /// DICOM only, after an update: the RT structure sets in the folder that
  /// were drawn on the series read (a radiotherapy export: the CT and the
  /// organs contoured on it), or, when it holds none, those in folders beside
  /// the CT's that were, each its file and its ROIs' names; out of
  /// range, nullptr and 0. Reading the file (FileName) gives its ROIs as
  /// segments; latticekit-surface and the planner do that when --label names
  /// an organ that only a structure set of the CT holds.
  int GetNumberOfStructureSets() const { return static_cast<int>(this->StructureSetFiles.size()); }
  const char* GetStructureSetFileName(int i) const;
  int GetNumberOfStructureSetROIs(int i) const;
  const char* GetStructureSetROIName(int i, int roi) const;
  ///@}

protected:
  vtkLKMedicalImageReader();
  ~vtkLKMedicalImageReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /// Reads the whole volume into Volume and PatientMatrix; false on error (reported).
  bool ReadVolume();

  char* FileName = nullptr;
  int SeriesIndex = -1;
  double SliceSpacing = 0.0;
  vtkMatrix4x4* PatientMatrix;
  vtkImageData* Volume;
  vtkMTimeType VolumeTime = 0;
  bool ReadStopped = false; ///< the last read was stopped (AbortExecute): the output is empty
  std::string FileFormat;
  std::string ReferenceImageFileName;
  int NumberOfSeries = 0;
  double GantryTilt = 0.0;
  double MinimumSliceGap = 0.0;
  double MaximumSliceGap = 0.0;
  int NumberOfInputSlices = 0;
  bool OrientationKnown = false;
  std::vector<std::string> StructureSetFiles;
  std::vector<std::vector<std::string>> StructureSetROINames;

private:
  vtkLKMedicalImageReader(const vtkLKMedicalImageReader&) = delete;
  void operator=(const vtkLKMedicalImageReader&) = delete;
};

#endif
