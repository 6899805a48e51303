#pragma once
/// \file vtkLKDICOMSeries.h
/// Private: find the DICOM series in a folder (vtkDICOMDirectory) and read one
/// into a regular volume in patient coordinates. vtkDICOMReader sorts the
/// slices and applies rescale slope and intercept; the geometry is then taken
/// from every slice's own ImagePositionPatient, so that gantry tilt (a shear)
/// and variable slice spacing are resolved by resampling rather than ignored.

#include <array>
#include <string>
#include <vector>

class vtkAlgorithm;
class vtkImageData;
class vtkMatrix4x4;

namespace lkvtk
{

struct DICOMSeriesInfo
{
  std::string uid;
  std::string description;
  std::string modality;
  std::string sopClass; ///< SOPClassUID of its first image (kSegmentationStorage: a DICOM SEG)
  std::vector<std::string> files;
};

/// The SOP class of a DICOM segmentation (DICOM SEG), as segmentation tools
/// and PACS store them: frames of 0/1 maps (BINARY), of occupancies
/// (FRACTIONAL) or of segment numbers (LABELMAP), each frame placed by its
/// own position and, but for LABELMAP, naming its segment.
constexpr const char* kSegmentationStorage = "1.2.840.10008.5.1.4.1.1.66.4";

/// A segment of a segmentation (a DICOM SEG's, a 3D Slicer .seg.nrrd's):
/// its label value (a DICOM SEG's SegmentNumber), its name, and the
/// component (layer) of the volume that holds it.
struct Segment
{
  int label = 1;
  std::string name;
  int layer = 0;
};

struct DICOMGeometryReport
{
  double gantryTiltDegrees = 0.0; ///< angle between slice normal and slice stacking direction
  double minGap = 0.0;            ///< smallest distance between consecutive slices (mm)
  double maxGap = 0.0;            ///< largest distance between consecutive slices (mm)
  double typicalGap = 0.0;        ///< the median distance between consecutive slices (mm)
  int inputSlices = 0;
  /// A gap more than 1.5 times the typical one (a slice lost in transfer, or
  /// a series with variable spacing): the ImagePositionPatient of the slices
  /// on either side (mm), and the gap along the slice normal.
  struct WideGap
  {
    std::array<double, 3> before, after;
    double gap = 0.0;
    int afterIndex = 0; ///< the slice after the gap, in position order
  };
  std::vector<WideGap> wideGaps; ///< in slice order
};

/// How many folder levels a DICOM folder is searched: a hospital's CD copied
/// to disk keeps its images a few folders down (DICOM/ST000000/SE000000/),
/// unless its DICOMDIR, which vtkDICOMDirectory reads instead, indexes them.
constexpr int kDICOMScanDepth = 8;

/// Lists the series found in the folder, largest first: its files and those
/// of its sub-folders down to `scanDepth` levels (1: the folder's own files;
/// a DICOMDIR in the folder is used instead when there is one). Returns false
/// with error set when the folder cannot be read or has no image series.
/// The scan of the files' headers is the first fifth of `progress`'s progress
/// (when given), the reading of the series (readDICOMSeries) the rest.
bool findDICOMSeries(const std::string& folder, std::vector<DICOMSeriesInfo>& series, std::string& error,
  vtkAlgorithm* progress = nullptr, int scanDepth = 1);

/// Reads the series and resamples it onto a regular grid in the slice frame:
/// x along the rows (ImageOrientationPatient[0..2]), y along the columns
/// ([3..5]), z along their cross product; the grid covers every slice's
/// footprint (tilted slices are shifted in plane). sliceSpacing <= 0 uses the
/// largest spacing not above the smallest gap that puts grid slices exactly on
/// the first and last input slices.
/// The output is float (rescaled values); patientMatrix maps its data
/// coordinates to DICOM patient (LPS) coordinates in millimetres.
bool readDICOMSeries(const DICOMSeriesInfo& series, double sliceSpacing, vtkImageData* output,
  vtkMatrix4x4* patientMatrix, DICOMGeometryReport& report, std::string& error, vtkAlgorithm* progress = nullptr);

/// Reads a DICOM SEG (one file) into a label volume on the grid of its
/// frames: x along the rows, y along the columns, z along their cross
/// product, from the lowest frame to the highest, with two empty slices
/// beyond each (frames a SEG leaves out are empty). Each voxel of a layer
/// (a component) holds the number of the segment there or 0; segments that
/// overlap go to layers of their own, as 3D Slicer packs them. FRACTIONAL
/// frames count where at least half the MaximumFractionalValue.
/// patientMatrix maps the output's data coordinates to patient (LPS) mm.
bool readDICOMSegmentation(const DICOMSeriesInfo& series, vtkImageData* output, vtkMatrix4x4* patientMatrix,
  std::vector<Segment>& segments, std::string& error, vtkAlgorithm* progress = nullptr);

} // namespace lkvtk
