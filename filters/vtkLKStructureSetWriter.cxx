#include "vtkLKStructureSetWriter.h"
#include "vtkLKAbort.h"
#include "vtkLKDICOMSeries.h"
#include "vtkLKText.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCutter.h>
#include <vtkDICOMCompiler.h>
#include <vtkDICOMItem.h>
#include <vtkDICOMMetaData.h>
#include <vtkDICOMSequence.h>
#include <vtkDICOMUtilities.h>
#include <vtkDICOMValue.h>
#include <vtkErrorCode.h>
#include <vtkInformation.h>
#include <vtkObjectFactory.h>
#include <vtkPlane.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStripper.h>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <sstream>

#include <sys/stat.h>

vtkStandardNewMacro(vtkLKStructureSetWriter);

namespace
{
using lkvtk::V3;

/// One contour plane: where it lies along the normal, and the image there
/// (none without a reference CT).
struct Plane
{
  double w = 0.0;
  std::string imageClass, imageInstance;
};

/// What the set takes from the CT it belongs to.
struct Reference
{
  vtkNew<vtkDICOMMetaData> first; // its first image's attributes (patient, study)
  std::string seriesUID, frameUID;
  lkvtk::SliceFrame frame;
  std::vector<Plane> planes; // sorted along frame.n
};

bool readReference(const std::string& path, int seriesIndex, Reference& ref, std::string& error)
{
  const bool isFolder = vtksys::SystemTools::FileIsDirectory(path);
  std::vector<lkvtk::DICOMSeriesInfo> series;
  if (!lkvtk::findDICOMSeries(isFolder ? path : vtksys::SystemTools::GetFilenamePath(path), series, error, nullptr,
        isFolder ? lkvtk::kDICOMScanDepth : 1))
    return false;
  if (isFolder && seriesIndex >= static_cast<int>(series.size()))
  {
    error = "ReferenceSeriesIndex " + std::to_string(seriesIndex) + " is out of range: the folder has " +
      std::to_string(series.size()) + " series";
    return false;
  }
  // The largest, as the reader takes it, the one chosen, or the file's.
  const int index = isFolder ? std::max(0, seriesIndex) : lkvtk::seriesHoldingFile(series, path);
  if (index < 0)
  {
    error = "'" + path + "' is not a DICOM image file";
    return false;
  }
  const lkvtk::DICOMSeriesInfo& chosen = series[static_cast<std::size_t>(index)];
  ref.seriesUID = chosen.uid;
  std::vector<lkvtk::ImagePosition> images;
  double iop[6];
  if (!lkvtk::readDICOMHeader(chosen.files.front(), ref.first, error) ||
    !lkvtk::readImagePositions(chosen, images, error))
    return false;
  if (ref.first->Get(DC::ImageOrientationPatient).GetNumberOfValues() < 6)
  {
    error = "the reference CT has no ImageOrientationPatient";
    return false;
  }
  ref.first->Get(DC::ImageOrientationPatient).GetValues(iop, 6);
  if (!lkvtk::sliceFrame(iop, ref.frame))
  {
    error = "the reference CT's ImageOrientationPatient is degenerate";
    return false;
  }
  for (const lkvtk::ImagePosition& image : images)
    ref.planes.push_back({ lkvtk::dot(ref.frame.n, image.position), image.sopClass, image.sopInstance });
  std::sort(ref.planes.begin(), ref.planes.end(), [](const Plane& a, const Plane& b) { return a.w < b.w; });
  ref.frameUID = ref.first->Get(DC::FrameOfReferenceUID).AsString();
  return true;
}

/// The closed contours of `surface` on the planes (normal n): for each
/// plane, its loops in patient mm, lying on it. Each plane is cut a micron
/// above itself (a surface from a label map has vertices, even faces, on the
/// slice planes, where a cut makes degenerate pieces), and the points are put
/// back onto it.
std::vector<std::vector<std::vector<V3>>> contoursOf(
  vtkPolyData* surface, const V3& n, const std::vector<Plane>& planes, int& open)
{
  constexpr double kAbove = 1e-3;
  std::vector<std::vector<std::vector<V3>>> out(planes.size());
  double bounds[6];
  surface->GetBounds(bounds);
  vtkNew<vtkPlane> plane;
  plane->SetOrigin(0.0, 0.0, 0.0);
  plane->SetNormal(n[0], n[1], n[2]);
  vtkNew<vtkCutter> cutter;
  cutter->SetInputData(surface);
  cutter->SetCutFunction(plane);
  cutter->GenerateTrianglesOff();
  int values = 0;
  for (const Plane& p : planes)
    cutter->SetValue(values++, p.w + kAbove);
  vtkNew<vtkStripper> loops;
  loops->SetInputConnection(cutter->GetOutputPort());
  loops->JoinContiguousSegmentsOn();
  loops->SetMaximumLength(100000); // its default, 1000 segments, cuts a skull's section into open pieces
  loops->Update();
  vtkPolyData* lines = loops->GetOutput();
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  auto cells = vtk::TakeSmartPointer(lines->GetLines()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    cells->GetCurrentCell(count, ids);
    if (count < 4 || ids[0] != ids[count - 1])
    {
      open += count >= 2 ? 1 : 0;
      continue;
    }
    double x[3];
    lines->GetPoint(ids[0], x);
    const double w = lkvtk::dot(n, V3{ x[0], x[1], x[2] }) - kAbove;
    const auto at = std::min_element(planes.begin(), planes.end(),
      [&](const Plane& a, const Plane& b) { return std::abs(a.w - w) < std::abs(b.w - w); });
    std::vector<V3> loop;
    for (vtkIdType i = 0; i + 1 < count; ++i)
    {
      lines->GetPoint(ids[i], x);
      const double off = lkvtk::dot(n, V3{ x[0], x[1], x[2] }) - at->w;
      loop.push_back({ x[0] - off * n[0], x[1] - off * n[1], x[2] - off * n[2] });
    }
    out[static_cast<std::size_t>(at - planes.begin())].push_back(loop);
  }
  return out;
}

std::string today(const char* format)
{
  char text[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(text, sizeof(text), format, std::localtime(&now));
  return text;
}
} // namespace

vtkLKStructureSetWriter::vtkLKStructureSetWriter()
{
  this->SetStructureSetLabel("latticekit");
}

vtkLKStructureSetWriter::~vtkLKStructureSetWriter()
{
  this->SetFileName(nullptr);
  this->SetReferenceFileName(nullptr);
  this->SetStructureSetLabel(nullptr);
}

void vtkLKStructureSetWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "ReferenceFileName: " << (this->ReferenceFileName ? this->ReferenceFileName : "(none)") << "\n";
  os << indent << "ReferenceSeriesIndex: " << this->ReferenceSeriesIndex << "\n";
  os << indent << "SliceSpacing: " << this->SliceSpacing << "\n";
  os << indent << "StructureSetLabel: " << (this->StructureSetLabel ? this->StructureSetLabel : "(none)") << "\n";
  os << indent << "ROIName:";
  for (std::size_t i = 0; i < this->ROINames.size(); ++i)
    os << (i ? ", " : " ") << "'" << this->ROINames[i] << "'";
  os << (this->ROINames.empty() ? " (defaults: ROI 1, ROI 2, ...)\n" : "\n");
  os << indent << "Markers: " << this->Markers.size() << "\n";
}

int vtkLKStructureSetWriter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Set(vtkAlgorithm::INPUT_IS_REPEATABLE(), 1);
  return 1;
}

void vtkLKStructureSetWriter::AddInputData(vtkPolyData* surface)
{
  this->AddInputDataInternal(0, surface);
}

void vtkLKStructureSetWriter::SetROIName(int i, const char* name)
{
  if (i < 0 || i > 10000)
  {
    vtkErrorMacro("SetROIName: input " << i << " is out of range (0 to 10000).");
    return;
  }
  if (static_cast<std::size_t>(i) >= this->ROINames.size())
    this->ROINames.resize(static_cast<std::size_t>(i) + 1);
  this->ROINames[static_cast<std::size_t>(i)] = name ? name : "";
  this->Modified();
}

void vtkLKStructureSetWriter::AddMarker(const char* name, double x, double y, double z)
{
  this->Markers.push_back({ name ? name : "", { x, y, z } });
  this->Modified();
}

void vtkLKStructureSetWriter::RemoveAllMarkers()
{
  if (!this->Markers.empty())
    this->Modified();
  this->Markers.clear();
}

const char* vtkLKStructureSetWriter::GetROIName(int i)
{
  return i >= 0 && static_cast<std::size_t>(i) < this->ROINames.size() ? this->ROINames[static_cast<std::size_t>(i)].c_str()
                                                                          : nullptr;
}

void vtkLKStructureSetWriter::WriteData()
{
  this->NumberOfContours = this->NumberOfOpenContours = 0;
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No FileName given.");
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    return;
  }
  // The file replaced is the one a link points to (the link stays); a pipe
  // or a device (/dev/null) is never replaced by a file.
  std::string target = this->FileName;
  if (vtksys::SystemTools::FileIsSymlink(target))
    target = vtksys::SystemTools::GetRealPath(target);
  struct stat info;
  if (stat(target.c_str(), &info) == 0 && !S_ISREG(info.st_mode) && !S_ISDIR(info.st_mode))
  {
    vtkErrorMacro("Cannot write '" << this->FileName << "': it is not a regular file.");
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
    return;
  }
  const int inputs = this->GetNumberOfInputConnections(0);
  std::vector<vtkPolyData*> surfaces;
  for (int i = 0; i < inputs; ++i)
  {
    vtkPolyData* surface = vtkPolyData::SafeDownCast(this->GetInputDataObject(0, i));
    if (!surface || surface->GetNumberOfPolys() == 0)
    {
      vtkErrorMacro("Input " << i << " has no faces: each input is a closed surface, an ROI.");
      this->SetErrorCode(vtkErrorCode::UserError);
      return;
    }
    // Each point (bounds skip NaN, and a cut through one writes a point at 0).
    bool finite = true;
    for (vtkIdType p = 0; p < surface->GetNumberOfPoints() && finite; ++p)
    {
      const double* x = surface->GetPoint(p);
      finite = std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
    }
    if (!finite)
    {
      vtkErrorMacro("Input " << i << " has a point whose coordinates are not numbers.");
      this->SetErrorCode(vtkErrorCode::UserError);
      return;
    }
    surfaces.push_back(surface);
  }

  // The names: UTF-8, each to be written in the set's character set; an
  // input without one is "ROI 1", "ROI 2", ...
  const std::string label = this->StructureSetLabel ? this->StructureSetLabel : "";
  std::string unfit =
    label.empty() ? std::string("is empty") : lkvtk::dicomTextProblem(label, lkvtk::kDICOMShortStringLength);
  if (!unfit.empty())
  {
    vtkErrorMacro("The StructureSetLabel '" << lkvtk::shownText(label, 80) << "' " << unfit << ".");
    this->SetErrorCode(vtkErrorCode::UserError);
    return;
  }
  std::vector<std::string> names;
  for (std::size_t i = 0; i < surfaces.size(); ++i)
  {
    const bool given = i < this->ROINames.size() && !this->ROINames[i].empty();
    names.push_back(given ? this->ROINames[i] : "ROI " + std::to_string(i + 1));
    if (!(unfit = lkvtk::dicomTextProblem(names.back(), lkvtk::kDICOMLongStringLength)).empty())
    {
      vtkErrorMacro(
        "The ROI name '" << lkvtk::shownText(names.back(), 80) << "' (input " << i << ") " << unfit << ".");
      this->SetErrorCode(vtkErrorCode::UserError);
      return;
    }
  }

  for (std::size_t k = 0; k < this->Markers.size(); ++k)
  {
    const Marker& m = this->Markers[k];
    unfit = m.name.empty() ? std::string("is empty") : lkvtk::dicomTextProblem(m.name, lkvtk::kDICOMLongStringLength);
    if (!unfit.empty())
    {
      vtkErrorMacro("The marker name '" << lkvtk::shownText(m.name, 80) << "' (marker " << k << ") " << unfit << ".");
      this->SetErrorCode(vtkErrorCode::UserError);
      return;
    }
    if (!std::isfinite(m.x[0]) || !std::isfinite(m.x[1]) || !std::isfinite(m.x[2]))
    {
      vtkErrorMacro("Marker " << k << " ('" << lkvtk::shownText(m.name, 80) << "') has a coordinate that is not a number.");
      this->SetErrorCode(vtkErrorCode::UserError);
      return;
    }
    names.push_back(m.name); // after the surfaces' names, as the ROIs follow
  }

  // The planes: the reference CT's slices, or axial planes SliceSpacing apart.
  Reference ref;
  std::string error;
  const bool referenced = this->ReferenceFileName && *this->ReferenceFileName;
  if (referenced && !readReference(this->ReferenceFileName, this->ReferenceSeriesIndex, ref, error))
  {
    vtkErrorMacro("Cannot use the reference CT '" << this->ReferenceFileName << "': " << error << ".");
    this->SetErrorCode(vtkErrorCode::FileFormatError);
    return;
  }
  if (!referenced)
  {
    if (!(this->SliceSpacing >= 0.01 && this->SliceSpacing <= 100.0))
    {
      vtkErrorMacro("SliceSpacing must be 0.01 to 100 mm, not " << this->SliceSpacing << ".");
      this->SetErrorCode(vtkErrorCode::UserError);
      return;
    }
    ref.frame = { { 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 }, { 0.0, 0.0, 1.0 } };
    double lo = VTK_DOUBLE_MAX, hi = VTK_DOUBLE_MIN;
    for (vtkPolyData* s : surfaces)
    {
      double b[6];
      s->GetBounds(b);
      lo = std::min(lo, b[4]);
      hi = std::max(hi, b[5]);
    }
    const double first = std::ceil(lo / this->SliceSpacing), last = std::floor(hi / this->SliceSpacing);
    if (last - first > 1.0e5)
    {
      vtkErrorMacro("The surfaces span " << hi - lo << " mm: too many planes of " << this->SliceSpacing << " mm.");
      this->SetErrorCode(vtkErrorCode::UserError);
      return;
    }
    for (double k = first; k <= last; ++k)
      ref.planes.push_back({ k * this->SliceSpacing, "", "" });
  }
  if (ref.frameUID.empty())
    ref.frameUID = vtkDICOMUtilities::GenerateUID(DC::FrameOfReferenceUID);

  // The set: patient and study of the reference CT (or new ones).
  // The character set goes with the names it spells.
  vtkNew<vtkDICOMMetaData> meta;
  for (vtkDICOMTag tag : { DC::SpecificCharacterSet, DC::PatientName, DC::PatientID, DC::PatientBirthDate,
         DC::PatientSex, DC::StudyInstanceUID, DC::StudyDate, DC::StudyTime, DC::StudyID, DC::AccessionNumber,
         DC::ReferringPhysicianName, DC::StudyDescription })
  {
    if (referenced && ref.first->Get(tag).IsValid())
      meta->Set(tag, ref.first->Get(tag));
  }
  // The names go in the CT's character set where it spells them (a Latin-1
  // CT's set stays Latin-1, for the systems that read that only); where it
  // cannot, the set is UTF-8 (ISO_IR 192), the patient's and study's text
  // converted to it.
  vtkDICOMCharacterSet characterSet = referenced
    ? vtkDICOMCharacterSet(ref.first->Get(DC::SpecificCharacterSet).AsString())
    : vtkDICOMCharacterSet(vtkDICOMCharacterSet::ISO_IR_6);
  auto spells = [&characterSet](const std::string& text) {
    std::size_t converted = 0;
    characterSet.FromUTF8(text.data(), text.size(), &converted);
    return converted == text.size();
  };
  if (!spells(label) || !std::all_of(names.begin(), names.end(), spells))
  {
    characterSet = vtkDICOMCharacterSet(vtkDICOMCharacterSet::ISO_IR_192);
    for (vtkDICOMTag tag : { DC::PatientName, DC::PatientID, DC::ReferringPhysicianName, DC::StudyID,
           DC::AccessionNumber, DC::StudyDescription })
      if (meta->Get(tag).IsValid())
      {
        const vtkDICOMValue& value = meta->Get(tag);
        meta->Set(tag, vtkDICOMValue::FromUTF8String(value.GetVR(), characterSet, lkvtk::dicomText(value)));
      }
    meta->Set(DC::SpecificCharacterSet, "ISO_IR 192");
  }
  if (!meta->Get(DC::StudyInstanceUID).IsValid())
    meta->Set(DC::StudyInstanceUID, vtkDICOMUtilities::GenerateUID(DC::StudyInstanceUID));
  // Type 2 attributes of the RT Structure Set IOD are present, empty when
  // unknown (a set not drawn on a CT, or a CT that lacks them), as the
  // standard asks and a PACS may check.
  for (vtkDICOMTag tag : { DC::PatientName, DC::PatientID, DC::PatientBirthDate, DC::PatientSex, DC::StudyDate,
         DC::StudyTime, DC::StudyID, DC::AccessionNumber, DC::ReferringPhysicianName, DC::OperatorsName })
  {
    if (!meta->Get(tag).IsValid())
      meta->Set(tag, "");
  }
  // A new series of one instance, each with its own UID (Type 1: a PACS
  // refuses an object without them; vtkDICOMCompiler writes the UIDs only
  // of elements the meta data holds).
  const std::string seriesUID = vtkDICOMUtilities::GenerateUID(DC::SeriesInstanceUID);
  const std::string instanceUID = vtkDICOMUtilities::GenerateUID(DC::SOPInstanceUID);
  meta->Set(DC::SeriesInstanceUID, seriesUID);
  meta->Set(DC::SOPInstanceUID, instanceUID);
  meta->Set(DC::SOPClassUID, lkvtk::kRTStructureSetStorage);
  meta->Set(DC::Modality, "RTSTRUCT");
  meta->Set(DC::SeriesNumber, 900.0);
  meta->Set(DC::InstanceNumber, 1.0);
  meta->Set(DC::SeriesDescription, "latticekit surfaces");
  meta->Set(DC::Manufacturer, "latticekit");
  meta->Set(DC::StructureSetLabel, vtkDICOMValue::FromUTF8String(vtkDICOMVR::SH, characterSet, label));
  meta->Set(DC::StructureSetDate, today("%Y%m%d"));
  meta->Set(DC::StructureSetTime, today("%H%M%S"));
  {
    vtkDICOMSequence images;
    for (const Plane& p : ref.planes)
      if (!p.imageInstance.empty())
      {
        vtkDICOMItem image;
        image.Set(DC::ReferencedSOPClassUID, p.imageClass);
        image.Set(DC::ReferencedSOPInstanceUID, p.imageInstance);
        images.AddItem(image);
      }
    vtkDICOMItem series, study, frame;
    frame.Set(DC::FrameOfReferenceUID, ref.frameUID);
    if (referenced) // the images the contours lie on
    {
      series.Set(DC::SeriesInstanceUID, ref.seriesUID);
      series.Set(DC::ContourImageSequence, images);
      study.Set(DC::ReferencedSOPClassUID, "1.2.840.10008.3.1.2.3.1"); // Detached Study Management, as the standard asks
      study.Set(DC::ReferencedSOPInstanceUID, meta->Get(DC::StudyInstanceUID).AsString());
      study.Set(DC::RTReferencedSeriesSequence, vtkDICOMSequence(series));
      frame.Set(DC::RTReferencedStudySequence, vtkDICOMSequence(study));
    }
    meta->Set(DC::ReferencedFrameOfReferenceSequence, vtkDICOMSequence(frame));
  }
  static const char* const colours[] = { "241\\214\\145", "216\\101\\79", "128\\174\\128", "111\\184\\210",
    "221\\130\\101", "144\\238\\144", "220\\245\\20", "78\\63\\0" };
  vtkDICOMSequence listed, contoured, observed;
  // An ROI in the set's three lists: its name, its contours, what it is.
  auto addROI = [&](int number, const std::string& name, const char* algorithm, const char* colour,
                  const vtkDICOMSequence& contours, const char* interpretedType) {
    vtkDICOMItem roi, item, observation;
    roi.Set(DC::ROINumber, static_cast<double>(number));
    roi.Set(DC::ReferencedFrameOfReferenceUID, ref.frameUID);
    roi.Set(DC::ROIName, vtkDICOMValue::FromUTF8String(vtkDICOMVR::LO, characterSet, name));
    roi.Set(DC::ROIGenerationAlgorithm, algorithm);
    listed.AddItem(roi);
    item.Set(DC::ReferencedROINumber, static_cast<double>(number));
    item.Set(DC::ROIDisplayColor, colour);
    item.Set(DC::ContourSequence, contours);
    contoured.AddItem(item);
    observation.Set(DC::ObservationNumber, static_cast<double>(number));
    observation.Set(DC::ReferencedROINumber, static_cast<double>(number));
    observation.Set(DC::RTROIInterpretedType, interpretedType);
    observation.Set(DC::ROIInterpreter, "");
    observed.AddItem(observation);
  };
  for (std::size_t i = 0; i < surfaces.size(); ++i)
  {
    this->UpdateProgress(static_cast<double>(i) / static_cast<double>(surfaces.size()));
    if (lkvtk::stopRequested(this, {})) // nothing written: an earlier file stays
      return;
    const int number = static_cast<int>(i) + 1;
    const std::string& name = names[i]; // the surfaces' names come first
    int open = 0;
    const auto perPlane = contoursOf(surfaces[i], ref.frame.n, ref.planes, open);
    this->NumberOfOpenContours += open;
    vtkDICOMSequence contours;
    for (std::size_t k = 0; k < perPlane.size(); ++k)
      for (const std::vector<V3>& loop : perPlane[k])
      {
        std::vector<double> xyz;
        for (const V3& p : loop)
          xyz.insert(xyz.end(), p.begin(), p.end());
        vtkDICOMItem contour;
        if (!ref.planes[k].imageInstance.empty())
        {
          vtkDICOMItem image;
          image.Set(DC::ReferencedSOPClassUID, ref.planes[k].imageClass);
          image.Set(DC::ReferencedSOPInstanceUID, ref.planes[k].imageInstance);
          contour.Set(DC::ContourImageSequence, vtkDICOMSequence(image));
        }
        contour.Set(DC::ContourGeometricType, "CLOSED_PLANAR");
        contour.Set(DC::NumberOfContourPoints, static_cast<double>(loop.size()));
        contour.Set(DC::ContourData, vtkDICOMValue(vtkDICOMVR::DS, xyz.data(), xyz.size()));
        contours.AddItem(contour);
        ++this->NumberOfContours;
      }
    if (contours.GetNumberOfItems() == 0)
    {
      if (open > 0)
        vtkErrorMacro("'" << name << "' (input " << i << ") has only open sections on the "
                          << (referenced ? "reference CT's slices" : "contour planes") << " (" << open
                          << " open pieces): the surface is not closed where they cut it (close it first: "
                             "latticekit-surface --close, or vtkLKMeshRepairFilter with hole filling).");
      else
        vtkErrorMacro("'" << name << "' (input " << i << ") crosses none of the "
                          << (referenced ? "reference CT's slices" : "contour planes")
                          << ": nothing to write for it.");
      this->SetErrorCode(vtkErrorCode::UserError);
      return;
    }
    addROI(number, name, "SEMIAUTOMATIC", colours[i % 8], contours, "ORGAN");
  }
  // The markers: one point each.
  for (std::size_t k = 0; k < this->Markers.size(); ++k)
  {
    vtkDICOMItem point;
    point.Set(DC::ContourGeometricType, "POINT");
    point.Set(DC::NumberOfContourPoints, 1.0);
    point.Set(DC::ContourData, vtkDICOMValue(vtkDICOMVR::DS, this->Markers[k].x, 3));
    addROI(static_cast<int>(surfaces.size() + k) + 1, names[surfaces.size() + k], "MANUAL", "140\\0\\115",
      vtkDICOMSequence(point), "MARKER");
  }
  meta->Set(DC::StructureSetROISequence, listed);
  meta->Set(DC::ROIContourSequence, contoured);
  meta->Set(DC::RTROIObservationsSequence, observed);
  if (this->NumberOfOpenContours > 0)
    vtkWarningMacro(<< this->NumberOfOpenContours
                    << " open piece(s) of contour left out: a surface is not closed where the planes cut it.");

  // Beside the destination first: a failed write leaves an earlier file whole.
  const std::string part = target + ".part";
  vtkNew<vtkDICOMCompiler> compiler;
  lkvtk::ErrorCatcher catcher(compiler);
  compiler->SetFileName(part.c_str());
  compiler->SetMetaData(meta);
  compiler->SetSeriesInstanceUID(seriesUID.c_str());
  compiler->SetSOPInstanceUID(instanceUID.c_str());
  compiler->WriteHeader();
  compiler->Close();
  std::string why = catcher.messages;
  const bool written = compiler->GetErrorCode() == 0 && why.empty();
  if (written && std::rename(part.c_str(), target.c_str()) != 0)
    why = std::strerror(errno); // a folder of that name, say
  if (!written || !why.empty())
  {
    vtksys::SystemTools::RemoveFile(part);
    vtkErrorMacro("Cannot write '" << this->FileName << "'" << (why.empty() ? "" : ": " + why) << ".");
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
    return;
  }
  this->UpdateProgress(1.0);
}
