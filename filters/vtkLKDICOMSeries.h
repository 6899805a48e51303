#pragma once
/// \file vtkLKDICOMSeries.h
/// Private: find the DICOM series in a folder (vtkDICOMDirectory) and read one
/// into a regular volume in patient coordinates. vtkDICOMReader sorts the
/// slices and applies rescale slope and intercept; the geometry is then taken
/// from every slice's own ImagePositionPatient, so that gantry tilt (a shear)
/// and variable slice spacing are resolved by resampling rather than ignored.

#include <vtkCallbackCommand.h>
#include <vtkNew.h>

#include <algorithm>
#include <array>
#include <functional>
#include <string>
#include <vector>

class vtkAlgorithm;
class vtkDICOMDirectory;
class vtkDICOMMetaData;
class vtkDICOMValue;
class vtkImageData;
class vtkMatrix4x4;

namespace lkvtk
{

using V3 = std::array<double, 3>;
inline double dot(const V3& a, const V3& b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
inline V3 cross(const V3& a, const V3& b)
{
  return { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
}
inline V3 sub(const V3& a, const V3& b)
{
  return { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
}

/// A DICOM text value (a name, a label, a description) in UTF-8, as the
/// tools print it and as --label and the planner's names compare with it:
/// converted from the character set its file declares (Latin-1, ISO 2022
/// Japanese, ...). Where a file declares none, bytes beyond ASCII are taken
/// as UTF-8 if they are valid UTF-8 and as Latin-1 (ISO_IR 100) otherwise,
/// as older systems wrote them; nothing is lost to U+FFFD.
std::string dicomText(const vtkDICOMValue& value);

/// The slice frame of an ImageOrientationPatient: the rows' direction r, the
/// columns' c and their cross product n.
struct SliceFrame
{
  V3 r, c, n;
};

/// Direction cosines are stored rounded (often to 6 decimals): they are made
/// orthonormal (Gram-Schmidt) so that the patient matrix is a rotation.
/// False when either is degenerate.
bool sliceFrame(const double iop[6], SliceFrame& frame);

/// Data coordinates on the frame's axes, from `origin`, to patient (LPS) mm.
void setPatientMatrix(vtkMatrix4x4* m, const SliceFrame& frame, const V3& origin);

/// Collects the messages of VTK errors raised by an object while it lives
/// (the object may outlive it: the observer goes with it).
struct ErrorCatcher
{
  std::string messages;
  vtkNew<vtkCallbackCommand> command;
  vtkObject* observed;
  unsigned long tag;
  explicit ErrorCatcher(vtkObject* object);
  ~ErrorCatcher();
  ErrorCatcher(const ErrorCatcher&) = delete;
  ErrorCatcher& operator=(const ErrorCatcher&) = delete;
};

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
  /// A CT whose images carry no RescaleIntercept (Type 1 for CT; a cone-beam
  /// scanner's export may leave it out): its stored values are taken as they
  /// are, which need not be Hounsfield units. The lowest value read, to say
  /// whether air looks like -1000 HU.
  bool ctWithoutRescale = false;
  double lowestValue = 0.0;
  /// A CT with a RescaleIntercept but no RescaleSlope (both are Type 1):
  /// the intercept was applied with a slope of 1.
  bool interceptWithoutSlope = false;
};

/// Reads a DICOM file's header (up to its pixel data) into `meta`; false
/// with error set when the file cannot be parsed (what could be read is kept).
bool readDICOMHeader(const std::string& file, vtkDICOMMetaData* meta, std::string& error);

/// The index of the series that holds `file` (by its full path), or -1.
int seriesHoldingFile(const std::vector<DICOMSeriesInfo>& series, const std::string& file);

/// An image of a series: its ImagePositionPatient and SOP identity.
struct ImagePosition
{
  V3 position;
  std::string sopClass, sopInstance;
};

/// Each image's position and SOP identity, in the series' file order, from
/// their headers alone; false with error set when one has no finite position.
bool readImagePositions(const DICOMSeriesInfo& series, std::vector<ImagePosition>& images, std::string& error);

/// How many folder levels a DICOM folder is searched: a hospital's CD copied
/// to disk keeps its images a few folders down (DICOM/ST000000/SE000000/),
/// unless its DICOMDIR, which vtkDICOMDirectory reads instead, indexes them.
constexpr int kDICOMScanDepth = 8;

/// Updates `dir` (its scan the first fifth of `progress`'s progress, when
/// given). When it read a DICOMDIR that lists files which are not there (a
/// CD copied in part, its files renamed), it sets the DICOMDIR aside
/// (IgnoreDicomdirOn, clearing what `catcher` caught of the first read) and
/// updates again, to scan the files themselves, and returns what to warn
/// of. Empty otherwise.
std::string updateDirectory(vtkDICOMDirectory* dir, vtkAlgorithm* progress = nullptr, ErrorCatcher* catcher = nullptr);

/// Lists the series found in the folder, largest first: its files and those
/// of its sub-folders down to `scanDepth` levels (1: the folder's own files;
/// a DICOMDIR in the folder is used instead when there is one). Returns false
/// with error set when the folder cannot be read or has no image series.
/// The scan of the files' headers is the first fifth of `progress`'s progress
/// (when given), the reading of the series (readDICOMSeries) the rest. A
/// DICOMDIR that names files which are not there is set aside and the
/// files scanned instead; `note` (when given) then says so, else is empty.
bool findDICOMSeries(const std::string& folder, std::vector<DICOMSeriesInfo>& series, std::string& error,
  vtkAlgorithm* progress = nullptr, int scanDepth = 1, std::string* note = nullptr);

/// A folder beside another (a sibling: a sub-folder of the same parent) and
/// what its first DICOM file is: a PACS, TCIA or 3D Slicer export keeps each
/// series of a study in a folder of its own, side by side, so an RT structure
/// set's or a DICOM SEG's CT is a folder away from it.
struct FolderBeside
{
  std::string folder;
  std::string seriesUID; ///< SeriesInstanceUID of its first DICOM file (in name order)
  std::string modality;  ///< Modality of that file (CT, RTSTRUCT, SEG, ...)
  std::string studyUID;  ///< its StudyInstanceUID
  std::string frameUID;  ///< its FrameOfReferenceUID (empty for most RT objects)
};

/// The most sub-folders a parent may have for its folders to be searched as
/// a study's series: more are a disk's or a home's folders, not a study's.
constexpr int kFoldersBesideLimit = 256;

/// The folders beside `folder` (its parent's other sub-folders, in name
/// order) that hold a DICOM file among their first few, each with what its
/// first DICOM file is. Only headers are read, one or a few per folder.
/// None when `folder` has no parent or the parent has more than
/// kFoldersBesideLimit sub-folders (then `crowded`, when given, is set).
std::vector<FolderBeside> foldersBeside(const std::string& folder, bool* crowded = nullptr);

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

/// Where a segment goes among the layers of a segmentation (each `voxels`
/// labels): the first layer it `fits` in (overlaps no other segment), as
/// 3D Slicer packs them, or a new empty one, appended. -1 when a new layer
/// would take the layers past 2e9 labels.
int layerFor(std::vector<std::vector<unsigned short>>& layers, long long voxels,
  const std::function<bool(const std::vector<unsigned short>&)>& fits);

/// Makes `output` a label volume of `dims` voxels of `spacing` mm, one
/// component per layer (each `dims` voxels, x fastest): unsigned char when no
/// label exceeds 255, else unsigned short; its scalars are named "Segments".
void setLayers(vtkImageData* output, const int dims[3], const double spacing[3],
  const std::vector<std::vector<unsigned short>>& layers, int largestLabel);

/// The SOP class of an RT structure set (RTSTRUCT), as radiotherapy planning
/// systems store the organs they contour: each ROI a stack of closed planar
/// contours in patient coordinates, without pixel data.
constexpr const char* kRTStructureSetStorage = "1.2.840.10008.5.1.4.1.1.481.3";

/// An RT structure set found in a folder: its file, its ROIs' names, and the
/// image series it references (SeriesInstanceUIDs).
struct StructureSetInfo
{
  std::string file;
  std::vector<std::string> roiNames;
  std::vector<std::string> referencedSeries;

  /// Whether it was drawn on the image series of that SeriesInstanceUID.
  bool drawnOn(const std::string& seriesUID) const
  {
    return std::find(referencedSeries.begin(), referencedSeries.end(), seriesUID) != referencedSeries.end();
  }
};

/// The RT structure sets in the folder (and its sub-folders down to
/// `scanDepth` levels, as findDICOMSeries searches): a folder read as its CT
/// says what else it holds.
std::vector<StructureSetInfo> findDICOMStructureSets(const std::string& folder, int scanDepth);

/// The RT structure sets in the folders beside `folder` (see foldersBeside):
/// a study exported one series to a folder keeps its sets beside its CT,
/// not in it. Searched: the folders whose first DICOM file is a set, and,
/// when `imageFile` (a file of the CT) is given, every file of those whose
/// first file is of the CT's study or frame of reference (a folder of the
/// study's RT objects, a dose or a plan first; or of images and a set).
std::vector<StructureSetInfo> findDICOMStructureSetsBeside(
  const std::string& folder, const std::string& imageFile = std::string());

/// The first file of the image series (a DICOM SEG is none) that the DICOM
/// object in `file` was drawn on: the series an RT structure set or a DICOM
/// SEG references by its SeriesInstanceUID, among `series` (those of its own
/// folder) or else in a folder beside its folder (see foldersBeside): one
/// whose first file is of that series, else one of the object's study or
/// frame of reference that holds it among other series. Empty
/// when it is in neither (or the file cannot be read).
std::string referencedImageFile(const std::string& file, const std::vector<DICOMSeriesInfo>& series);

/// Whether `file` is a DICOM RT structure set (its header is read).
bool isDICOMStructureSet(const std::string& file);

/// Reads an RT structure set (one file) into a label volume: each ROI with
/// closed planar contours is a segment, its label its ROINumber (or its
/// place in the list, 1 up, when the numbers do not fit 1 to 65535), its
/// name its ROIName; voxels whose centre lies inside a contour of its slice
/// are the ROI's (even-odd, so a contour inside another is a hole). ROIs
/// that overlap go to layers of their own, as a DICOM SEG's.
///
/// The grid: when `imageSeries` (the image series of the file's folder), or
/// a folder beside the file's (see foldersBeside), holds the series the
/// structure set references, its slice frame and pixel
/// lattice, and its slices when they are evenly spaced and the contours lie
/// on them; otherwise the contours' own frame and 1 mm pixels (or the slice
/// spacing or the contours' median point spacing, when finer, down to 0.5 mm
/// within 1e8 voxels, 1e9 over its ROIs), and slices on the contours' planes, spaced by the
/// smallest gap between them. Two empty slices and pixels lie beyond the
/// contours on each side. Slices an ROI skips between two of its contours
/// (a gap of up to twice its usual contour spacing) are filled by
/// shape-based interpolation (the blend of the two contours' signed distance
/// maps); wider gaps are left empty. Contours of other types (POINT,
/// OPEN_PLANAR) are not read. `notes` says what the caller should warn
/// about: ROIs without closed contours, the grid guessed, planes moved onto
/// it, slices an ROI skips. `referencedImage`: a file of the image series
/// the set references, found there, or empty (as
/// referencedImageFile gives it, without parsing the set's contours again).
bool readDICOMStructureSet(const std::string& file, const std::vector<DICOMSeriesInfo>& imageSeries,
  vtkImageData* output, vtkMatrix4x4* patientMatrix, std::vector<Segment>& segments,
  std::vector<std::string>& notes, std::string& referencedImage, std::string& error,
  vtkAlgorithm* progress = nullptr);

} // namespace lkvtk
