/**
 * @class   vtkLKStructureSetWriter
 * @brief   Writes closed surfaces as the ROIs of a DICOM RT structure set.
 *
 * The way back into the hospital's DICOM world: a bone surface, a planned
 * resection piece or a segment, in patient (LPS) millimetres as
 * vtkLKBoneSurfaceFilter and the planner give them, becomes an ROI of an RT
 * structure set (RTSTRUCT) that PACS viewers and planning systems show over
 * the CT. Each input (port 0 takes several connections) is one ROI, cut by
 * VTK (vtkCutter, vtkStripper) into a closed polygon per slice plane
 * (CLOSED_PLANAR; a hollow section gives its inner loop too, which readers
 * fill even-odd as a hole).
 *
 * ReferenceFileName names the CT the surfaces were made from (a DICOM folder,
 * or a file of the series): the set then belongs to its patient, study and
 * frame of reference, references its images, and its contours lie on the
 * CT's slices, each naming its image. Without one, the contours lie on axial
 * planes SliceSpacing mm apart and the set has UIDs of its own (a file for a
 * viewer, not tied to a scan).
 *
 * ROINames gives each input's ROIName (default "ROI 1", "ROI 2", ...);
 * names and the StructureSetLabel are UTF-8 text within DICOM's rules (64
 * and 16 characters, no control character or backslash; otherwise Write
 * fails and says why). They are written in the reference CT's character set
 * where it spells them; where it does not (a CT in ASCII or Latin-1, a name
 * in Greek), the set is UTF-8 (ISO_IR 192), its patient's and study's text
 * converted. vtkLKMedicalImageReader gives such names back in UTF-8. ROINumbers are 1, 2, ... in input order,
 * then the markers (AddMarker: a point each, POINT contours of
 * interpreted type MARKER, which planning systems show as landmarks and
 * vtkLKMedicalImageReader passes over with a note). Open contours (a surface that is
 * not closed, cut where it is open) are left out with a warning. The file is
 * written beside its destination and renamed over it only when complete, so
 * a failed write leaves an earlier file as it was.
 *
 * vtkLKMedicalImageReader reads such a set back (RTSTRUCT support).
 */
#ifndef vtkLKStructureSetWriter_h
#define vtkLKStructureSetWriter_h

#include "LatticeKitFiltersModule.h"
#include "vtkWriter.h"

#include <string>

class vtkPolyData;
#include <vector>

class LATTICEKITFILTERS_EXPORT vtkLKStructureSetWriter : public vtkWriter
{
public:
  static vtkLKStructureSetWriter* New();
  vtkTypeMacro(vtkLKStructureSetWriter, vtkWriter);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// Adds a surface (an ROI) as one more input; AddInputConnection does the
  /// same for a pipeline's output.
  void AddInputData(vtkPolyData* surface);

  ///@{
  /// The file to write (.dcm).
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /// The DICOM CT the surfaces lie on (a folder, or a file of the series);
  /// none (default): axial planes SliceSpacing apart, UIDs of its own.
  vtkSetStringMacro(ReferenceFileName);
  vtkGetStringMacro(ReferenceFileName);
  ///@}

  ///@{
  /// Which series of a reference folder (numbered as vtkLKMedicalImageReader
  /// numbers them, largest first); -1 (default): the largest.
  vtkSetMacro(ReferenceSeriesIndex, int);
  vtkGetMacro(ReferenceSeriesIndex, int);
  ///@}

  ///@{
  /// The spacing of the contour planes in mm without a reference CT
  /// (default 1).
  vtkSetMacro(SliceSpacing, double);
  vtkGetMacro(SliceSpacing, double);
  ///@}

  ///@{
  /// The ROIName of input i (default "ROI i+1").
  void SetROIName(int i, const char* name);
  const char* GetROIName(int i);
  ///@}

  ///@{
  /// The StructureSetLabel (default "latticekit"; up to 16 characters).
  vtkSetStringMacro(StructureSetLabel);
  vtkGetStringMacro(StructureSetLabel);
  ///@}

  ///@{
  /// Points to mark, written after the surfaces as ROIs of one point each
  /// (ContourGeometricType POINT, RTROIInterpretedType MARKER): landmarks, a
  /// measured distance's ends. A name follows the ROI names' rules.
  void AddMarker(const char* name, double x, double y, double z);
  void RemoveAllMarkers();
  int GetNumberOfMarkers() const { return static_cast<int>(this->Markers.size()); }
  ///@}

  /// After a write: how many contours were written, and how many open
  /// pieces of contour (where a surface is not closed) were left out.
  int GetNumberOfContours() const { return this->NumberOfContours; }
  int GetNumberOfOpenContours() const { return this->NumberOfOpenContours; }

protected:
  vtkLKStructureSetWriter();
  ~vtkLKStructureSetWriter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  void WriteData() override;

  char* FileName = nullptr;
  char* ReferenceFileName = nullptr;
  char* StructureSetLabel = nullptr;
  double SliceSpacing = 1.0;
  int ReferenceSeriesIndex = -1;
  std::vector<std::string> ROINames;
  struct Marker
  {
    std::string name;
    double x[3];
  };
  std::vector<Marker> Markers;
  int NumberOfContours = 0;
  int NumberOfOpenContours = 0;

private:
  vtkLKStructureSetWriter(const vtkLKStructureSetWriter&) = delete;
  void operator=(const vtkLKStructureSetWriter&) = delete;
};

#endif
