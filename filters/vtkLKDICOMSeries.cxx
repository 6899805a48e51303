#include "vtkLKDICOMSeries.h"
#include "vtkLKProgressRelay.h"
#include "vtkLKText.h"

#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDICOMDictionary.h>
#include <vtkDICOMDirectory.h>
#include <vtkDICOMItem.h>
#include <vtkDICOMMetaData.h>
#include <vtkDICOMMetaDataAdapter.h>
#include <vtkDICOMParser.h>
#include <vtkDICOMReader.h>
#include <vtkDICOMUtilities.h>
#include <vtkDICOMValue.h>
#include <vtkErrorCode.h>
#include <vtkFloatArray.h>
#include <vtkImageCast.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkSMPTools.h>
#include <vtkStringArray.h>
#include <vtksys/Directory.hxx>
#include <vtksys/SystemTools.hxx>

#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <numeric>
#include <optional>
#include <sstream>
#include <type_traits>

namespace lkvtk
{

std::string dicomText(const vtkDICOMValue& value)
{
  // ISO 2022 sets (Japanese, Korean) are 7-bit, their text switched by
  // escape sequences: only ASCII itself is taken as it is.
  if (value.GetCharacterSet() != vtkDICOMCharacterSet::ISO_IR_6)
    return value.AsUTF8String();
  const std::string raw = value.AsString(); // declared none (or ASCII, wrongly)
  return isUTF8(raw) ? raw : vtkDICOMCharacterSet(vtkDICOMCharacterSet::ISO_IR_100).ToUTF8(raw);
}

ErrorCatcher::ErrorCatcher(vtkObject* object)
  : observed(object)
{
  command->SetClientData(this);
  command->SetCallback([](vtkObject*, unsigned long, void* clientData, void* callData) {
    auto* self = static_cast<ErrorCatcher*>(clientData);
    if (callData)
    {
      if (!self->messages.empty())
      {
        self->messages += "; ";
      }
      std::string m = static_cast<const char*>(callData);
      while (!m.empty() && (m.back() == '\n' || m.back() == ' '))
      {
        m.pop_back();
      }
      self->messages += m;
    }
  });
  tag = object->AddObserver(vtkCommand::ErrorEvent, command);
}

ErrorCatcher::~ErrorCatcher()
{
  observed->RemoveObserver(tag);
}

bool sliceFrame(const double iop[6], SliceFrame& frame)
{
  V3 r{ iop[0], iop[1], iop[2] }, c{ iop[3], iop[4], iop[5] };
  const double rn = std::sqrt(dot(r, r));
  if (!(rn > 0.5))
    return false;
  for (double& v : r)
    v /= rn;
  const double rc = dot(r, c);
  for (std::size_t a = 0; a < 3; ++a)
    c[a] -= rc * r[a];
  const double cn = std::sqrt(dot(c, c));
  if (!(cn > 0.5))
    return false;
  for (double& v : c)
    v /= cn;
  frame = { r, c, cross(r, c) };
  return true;
}

void setPatientMatrix(vtkMatrix4x4* m, const SliceFrame& frame, const V3& origin)
{
  m->Identity();
  for (std::size_t row = 0; row < 3; ++row)
  {
    m->SetElement(static_cast<int>(row), 0, frame.r[row]);
    m->SetElement(static_cast<int>(row), 1, frame.c[row]);
    m->SetElement(static_cast<int>(row), 2, frame.n[row]);
    m->SetElement(static_cast<int>(row), 3, origin[row]);
  }
}

namespace
{
/// vtkDICOMReader whose compressed slices (JPEG, JPEG-LS, JPEG 2000, which
/// it hands to GDCM) fail loudly. vtkDICOMReader ignores whether GDCM decoded
/// the pixel data: a damaged slice that GDCM gives up on leaves the buffer as
/// it was, and the volume gets a blank or stale slice without a word. GDCM
/// writes nothing when it fails (seen on damaged JPEG Lossless, JPEG-LS and
/// JPEG 2000 files), so the buffer is filled with a byte pattern first and a
/// buffer that still holds only that pattern is a slice not decoded.
class CheckedDICOMReader : public vtkDICOMReader
{
public:
  static CheckedDICOMReader* New();
  vtkTypeMacro(CheckedDICOMReader, vtkDICOMReader);

protected:
  CheckedDICOMReader() = default;

  bool ReadFileDelegated(const char* filename, int fileIdx, unsigned char* buffer, vtkIdType bufferSize) override
  {
    constexpr unsigned char kUnwritten = 0xA5;
    std::memset(buffer, kUnwritten, static_cast<std::size_t>(bufferSize));
    const bool read = this->Superclass::ReadFileDelegated(filename, fileIdx, buffer, bufferSize);
    const bool written =
      read && std::any_of(buffer, buffer + bufferSize, [](unsigned char b) { return b != kUnwritten; });
    if (!written)
    {
      const std::string uid = this->MetaData->Get(fileIdx, DC::TransferSyntaxUID).AsString();
      const char* name = vtkDICOMUtilities::GetUIDName(uid.c_str());
      this->SetErrorCode(vtkErrorCode::FileFormatError);
      vtkErrorMacro("'" << filename << "': its pixel data, compressed as " << (name && *name ? name : "?") << " ("
                        << uid << "), could not be decoded"
                        << (read ? " (the compressed data is damaged)" : "") << ".");
    }
    return written;
  }
};
vtkStandardNewMacro(CheckedDICOMReader);

/// Runs `reader` (set up by the caller) over `files`, its progress the part
/// from 0.2 to `progressEnd` of `progress`'s; false with error "cannot read
/// the DICOM <what>: ..." when it fails.
bool readFiles(CheckedDICOMReader* reader, const std::vector<std::string>& files, const char* what,
  vtkAlgorithm* progress, double progressEnd, std::string& error)
{
  vtkNew<vtkStringArray> names;
  for (const std::string& f : files)
    names->InsertNextValue(f);
  ErrorCatcher catcher(reader);
  reader->SetFileNames(names);
  reader->SetMemoryRowOrderToFileNative(); // row 0 in memory is the first row in the file
  {
    std::optional<ProgressRelay> relay;
    if (progress)
      relay.emplace(progress, reader, 0.2, progressEnd);
    reader->Update();
  }
  if (reader->GetErrorCode() != 0 || !catcher.messages.empty())
  {
    error = std::string("cannot read the DICOM ") + what + ": " +
      (catcher.messages.empty() ? std::string("the reader failed") : catcher.messages);
    return false;
  }
  return true;
}

/// The names in `folder` but "." and "..", in name order (a listing's own
/// order is the disk's); none when it cannot be listed.
std::vector<std::string> namesIn(const std::string& folder)
{
  std::vector<std::string> names;
  vtksys::Directory listing;
  if (!listing.Load(folder))
    return names;
  for (unsigned long i = 0; i < listing.GetNumberOfFiles(); ++i)
    if (const std::string name = listing.GetFile(i); name != "." && name != "..")
      names.push_back(name);
  std::sort(names.begin(), names.end());
  return names;
}

/// The transfer syntaxes vtkDICOM (as Debian builds it, with GDCM) cannot
/// parse or decode, by UID, with their names.
const char* unreadableTransferSyntax(const std::string& uid)
{
  static const std::map<std::string, const char*> names = {
    { "1.2.840.10008.1.2.1.99", "Deflated Explicit VR Little Endian" },
    { "1.2.840.10008.1.2.4.110", "JPEG XL Lossless" },
    { "1.2.840.10008.1.2.4.111", "JPEG XL JPEG Recompression" },
    { "1.2.840.10008.1.2.4.112", "JPEG XL" },
    { "1.2.840.10008.1.2.4.201", "High-Throughput JPEG 2000 Lossless" },
    { "1.2.840.10008.1.2.4.202", "High-Throughput JPEG 2000 with RPCL Options Lossless" },
    { "1.2.840.10008.1.2.4.203", "High-Throughput JPEG 2000" },
  };
  const auto it = names.find(uid);
  return it == names.end() ? nullptr : it->second;
}

/// Why a folder in which no image series was found may hold one all the
/// same: DICOM files in a transfer syntax that cannot be read here (the
/// folder's files and its sub-folders' down to `depth` levels, at most 64
/// files looked at). Empty when none is.
std::string unreadableFilesNote(const std::string& folder, int depth)
{
  std::map<std::string, int> found;
  int looked = 0;
  std::vector<std::pair<std::string, int>> folders{ { folder, 1 } };
  for (std::size_t k = 0; k < folders.size() && looked < 64; ++k)
    for (const std::string& name : namesIn(folders[k].first))
    {
      if (looked >= 64)
        break;
      const std::string path = folders[k].first + "/" + name;
      struct stat info;
      if (stat(path.c_str(), &info) != 0)
        continue;
      if (S_ISDIR(info.st_mode))
      {
        if (folders[k].second < depth)
          folders.push_back({ path, folders[k].second + 1 });
        continue;
      }
      if (!S_ISREG(info.st_mode))
        continue;
      ++looked;
      vtkNew<vtkDICOMMetaData> meta;
      std::string ignored;
      readDICOMHeader(path, meta, ignored); // the file meta information comes first
      const std::string syntax = meta->Get(DC::TransferSyntaxUID).AsString();
      if (unreadableTransferSyntax(syntax))
        ++found[syntax];
    }
  std::string note;
  for (const auto& [syntax, count] : found)
    note += std::string(note.empty() ? "" : "; ") + std::to_string(count) + " of the files looked at " +
      (count == 1 ? "is" : "are") + " DICOM in the transfer syntax " + unreadableTransferSyntax(syntax) + " (" +
      syntax + "), which cannot be read here";
  if (!note.empty())
    note += ": convert them to an uncompressed one first (for example gdcmconv --explicit IN OUT, or dcmconv +te "
            "IN OUT)";
  return note;
}
} // namespace

bool readDICOMHeader(const std::string& file, vtkDICOMMetaData* meta, std::string& error)
{
  vtkNew<vtkDICOMParser> parser;
  ErrorCatcher catcher(parser);
  parser->SetFileName(file.c_str());
  parser->SetMetaData(meta);
  parser->Update();
  if (parser->GetErrorCode() != 0 || !catcher.messages.empty())
  {
    error = "cannot read the DICOM file '" + file + "'" + (catcher.messages.empty() ? "" : ": " + catcher.messages);
    return false;
  }
  return true;
}

int seriesHoldingFile(const std::vector<DICOMSeriesInfo>& series, const std::string& file)
{
  const std::string wanted = vtksys::SystemTools::CollapseFullPath(file);
  for (std::size_t s = 0; s < series.size(); ++s)
    for (const std::string& f : series[s].files)
      if (vtksys::SystemTools::CollapseFullPath(f) == wanted)
        return static_cast<int>(s);
  return -1;
}

bool readImagePositions(const DICOMSeriesInfo& series, std::vector<ImagePosition>& images, std::string& error)
{
  images.clear();
  for (const std::string& file : series.files)
  {
    vtkNew<vtkDICOMMetaData> meta;
    double ipp[3];
    if (!readDICOMHeader(file, meta, error))
      return false;
    if (meta->Get(DC::ImagePositionPatient).GetNumberOfValues() < 3)
    {
      error = "the image '" + file + "' has no ImagePositionPatient";
      return false;
    }
    meta->Get(DC::ImagePositionPatient).GetValues(ipp, 3);
    if (!std::isfinite(ipp[0] + ipp[1] + ipp[2]))
    {
      error = "the image '" + file + "' has a position that is not a number";
      return false;
    }
    images.push_back({ { ipp[0], ipp[1], ipp[2] }, meta->Get(DC::SOPClassUID).AsString(),
      meta->Get(DC::SOPInstanceUID).AsString() });
  }
  return true;
}

std::string updateDirectory(vtkDICOMDirectory* dir, vtkAlgorithm* progress, ErrorCatcher* catcher)
{
  auto update = [&] {
    std::optional<ProgressRelay> relay;
    if (progress)
      relay.emplace(progress, dir, 0.0, 0.2);
    dir->Update();
  };
  update();
  if (!dir->GetFileSetID() || dir->GetIgnoreDicomdir())
    return {};
  int missing = 0, listed = 0;
  for (int i = 0; i < dir->GetNumberOfSeries(); ++i)
  {
    vtkStringArray* files = dir->GetFileNamesForSeries(i);
    for (vtkIdType f = 0; f < files->GetNumberOfValues(); ++f, ++listed)
      missing += !vtksys::SystemTools::FileExists(files->GetValue(f), true);
  }
  if (missing == 0)
    return {};
  if (catcher)
    catcher->messages.clear(); // the DICOMDIR's read's
  dir->IgnoreDicomdirOn();
  update();
  return "its DICOMDIR lists " + std::to_string(listed) + " files, " + std::to_string(missing) + " of which " +
    (missing == 1 ? "is" : "are") + " not there (a CD copied in part, or its files moved): the folder's files were read instead";
}

bool findDICOMSeries(const std::string& folder, std::vector<DICOMSeriesInfo>& series, std::string& error,
  vtkAlgorithm* progress, int scanDepth, std::string* note)
{
  series.clear();
  if (note)
    note->clear();
  vtkNew<vtkDICOMDirectory> dir;
  ErrorCatcher catcher(dir);
  dir->SetDirectoryName(folder.c_str());
  dir->SetScanDepth(std::max(1, scanDepth));
  dir->RequirePixelDataOn();
  const std::string stale = updateDirectory(dir, progress, &catcher);
  if (note)
    *note = stale;
  for (int i = 0; i < dir->GetNumberOfSeries(); ++i)
  {
    DICOMSeriesInfo info;
    vtkStringArray* files = dir->GetFileNamesForSeries(i);
    for (vtkIdType f = 0; f < files->GetNumberOfValues(); ++f)
    {
      info.files.push_back(files->GetValue(f));
    }
    vtkDICOMMetaData* meta = dir->GetMetaDataForSeries(i);
    if (meta)
    {
      info.uid = meta->Get(DC::SeriesInstanceUID).AsString();
      info.description = dicomText(meta->Get(DC::SeriesDescription));
      info.modality = meta->Get(DC::Modality).AsString();
      info.sopClass = meta->Get(DC::SOPClassUID).AsString();
    }
    series.push_back(info);
  }
  std::stable_sort(series.begin(), series.end(),
    [](const DICOMSeriesInfo& a, const DICOMSeriesInfo& b) { return a.files.size() > b.files.size(); });
  if (series.empty())
  {
    error = "no DICOM image series found in '" + folder + "'" +
      (scanDepth > 1 ? " or in its sub-folders (" + std::to_string(scanDepth - 1) + " levels down)" : "");
    if (!catcher.messages.empty())
    {
      error += " (" + catcher.messages + ")";
    }
    const std::string unreadable = unreadableFilesNote(folder, std::max(1, scanDepth));
    if (!unreadable.empty())
      error += ": " + unreadable;
    return false;
  }
  return true;
}

std::vector<FolderBeside> foldersBeside(const std::string& folder, bool* crowded)
{
  if (crowded)
    *crowded = false;
  std::vector<FolderBeside> found;
  const std::string own = vtksys::SystemTools::CollapseFullPath(folder.empty() ? "." : folder);
  const std::string parent = vtksys::SystemTools::GetParentDirectory(own);
  if (parent.empty() || parent == own)
    return found;
  std::vector<std::string> siblings; // in name order
  for (const std::string& name : namesIn(parent))
  {
    const std::string path = parent + (parent.back() == '/' ? "" : "/") + name;
    if (!vtksys::SystemTools::FileIsDirectory(path) || vtksys::SystemTools::CollapseFullPath(path) == own)
      continue;
    siblings.push_back(path);
    if (static_cast<int>(siblings.size()) > kFoldersBesideLimit)
    {
      if (crowded)
        *crowded = true;
      return {};
    }
  }
  for (const std::string& sibling : siblings)
  {
    std::vector<std::string> names; // in name order
    for (const std::string& name : namesIn(sibling))
    {
      // Regular files only: opening a pipe or a device would wait for ever.
      struct stat info;
      if (stat((sibling + "/" + name).c_str(), &info) == 0 && S_ISREG(info.st_mode))
        names.push_back(name);
    }
    // A licence or a README may come first; a DICOMDIR names no series.
    for (std::size_t i = 0; i < names.size() && i < 4; ++i)
    {
      vtkNew<vtkDICOMMetaData> meta;
      std::string ignored;
      if (!readDICOMHeader(sibling + "/" + names[i], meta, ignored))
        continue;
      const std::string uid = meta->Get(DC::SeriesInstanceUID).AsString();
      if (uid.empty())
        continue;
      found.push_back({ sibling, uid, meta->Get(DC::Modality).AsString(), meta->Get(DC::StudyInstanceUID).AsString(),
        meta->Get(DC::FrameOfReferenceUID).AsString() });
      break;
    }
  }
  return found;
}

bool readDICOMSeries(const DICOMSeriesInfo& series, double sliceSpacing, vtkImageData* output,
  vtkMatrix4x4* patientMatrix, DICOMGeometryReport& report, std::string& error, vtkAlgorithm* progress)
{
  vtkNew<CheckedDICOMReader> reader;
  reader->TimeAsVectorOff();
  if (!readFiles(reader, series.files, "series", progress, 0.95, error)) // the resampling after it is quick
    return false;
  vtkImageData* raw = reader->GetOutput();
  int dims[3];
  raw->GetDimensions(dims);
  if (raw->GetNumberOfPoints() == 0)
  {
    error = "the DICOM series gives no volume: vtkDICOMReader read no voxel of its images";
    return false;
  }
  vtkDICOMMetaData* meta = reader->GetMetaData();
  if (raw->GetNumberOfScalarComponents() != 1)
  {
    // Several values per voxel: colour pixels, or images vtkDICOMReader
    // could not place apart (frames without their orientation or positions,
    // time points), which it stacks as components.
    error = meta->Get(DC::SamplesPerPixel).AsInt() > 1
      ? "the DICOM series holds colour images; only greyscale (CT) volumes are supported"
      : "the DICOM series' images cannot be stacked into one volume: several lie at one position (time points), "
        "or the frames of a multi-frame file lack their orientation or positions";
    return false;
  }
  // The enhanced multi-frame form keeps the rescale in its functional
  // groups. vtkDICOMReader rescales only with both the intercept and the
  // slope; DICOM's slope is 1 when none is needed, so an intercept alone is
  // applied below, to the float copy the resampling reads.
  double interceptAlone = 0.0;
  {
    vtkDICOMMetaDataAdapter attributes(meta);
    const bool ct = attributes->Get(DC::Modality).AsString() == "CT";
    report.ctWithoutRescale = ct && !attributes->Has(DC::RescaleIntercept);
    report.interceptWithoutSlope = ct && attributes->Has(DC::RescaleIntercept) && !attributes->Has(DC::RescaleSlope);
    if (report.interceptWithoutSlope)
      interceptAlone = attributes->Get(DC::RescaleIntercept).AsDouble();
  }
  vtkIntArray* fileIndex = reader->GetFileIndexArray();
  const int nslices = dims[2];
  if (fileIndex->GetNumberOfTuples() != nslices)
  {
    error = "the DICOM series has several frames or time points per position; only 3D volumes are supported";
    return false;
  }
  report.inputSlices = nslices;

  // Geometry of every slice. An attribute of slice k is looked up in its
  // file and frame: an enhanced multi-frame file (one file, a frame per
  // slice) keeps the geometry in its shared and per-frame functional groups,
  // which vtkDICOMMetaData searches when given the frame.
  vtkIntArray* frameIndex = reader->GetFrameIndexArray();
  auto attribute = [&](int k, vtkDICOMTag tag) -> const vtkDICOMValue& {
    const int file = static_cast<int>(fileIndex->GetComponent(k, 0));
    const int frame =
      frameIndex && frameIndex->GetNumberOfTuples() > k ? static_cast<int>(frameIndex->GetComponent(k, 0)) : 0;
    return meta->Get(file, frame, tag);
  };
  // The values of a numeric attribute, or false when it is absent or short
  // (vtkDICOMValue::GetValues reads beyond a value that holds fewer).
  auto numbers = [&](int k, vtkDICOMTag tag, double* out, unsigned int count) {
    const vtkDICOMValue& v = attribute(k, tag);
    if (!v.IsValid() || v.GetNumberOfValues() < count)
      return false;
    v.GetValues(out, count);
    return true;
  };
  double iop[6];
  double ps[2];
  if (!numbers(0, DC::ImageOrientationPatient, iop, 6) || !numbers(0, DC::PixelSpacing, ps, 2))
  {
    error = "the DICOM series has no ImageOrientationPatient or PixelSpacing";
    return false;
  }
  SliceFrame frame;
  if (!sliceFrame(iop, frame))
  {
    error = "the DICOM ImageOrientationPatient is degenerate";
    return false;
  }
  const V3 &r = frame.r, &c = frame.c, &n = frame.n;
  const double dx = ps[1], dy = ps[0]; // PixelSpacing is (row spacing, column spacing)
  if (!(dx > 0.0) || !(dy > 0.0))
  {
    error = "the DICOM PixelSpacing is not positive";
    return false;
  }
  struct Slice
  {
    int index; // slice in the reader's output
    V3 ipp;
    double z;
  };
  std::vector<Slice> slices(static_cast<std::size_t>(nslices));
  for (int k = 0; k < nslices; ++k)
  {
    double p[3];
    if (!numbers(k, DC::ImagePositionPatient, p, 3))
    {
      error = "a DICOM slice has no ImagePositionPatient";
      return false;
    }
    double o[6];
    if (!numbers(k, DC::ImageOrientationPatient, o, 6))
    {
      error = "a DICOM slice has no ImageOrientationPatient";
      return false;
    }
    for (int i = 0; i < 6; ++i)
    {
      if (std::abs(o[i] - iop[i]) > 1e-4)
      {
        error = "the slices of the DICOM series do not share one ImageOrientationPatient";
        return false;
      }
    }
    slices[static_cast<std::size_t>(k)] = { k, { p[0], p[1], p[2] }, dot(n, V3{ p[0], p[1], p[2] }) };
  }
  std::sort(slices.begin(), slices.end(), [](const Slice& a, const Slice& b) { return a.z < b.z; });
  report.minGap = std::numeric_limits<double>::max();
  report.maxGap = 0.0;
  for (std::size_t k = 1; k < slices.size(); ++k)
  {
    const double gap = slices[k].z - slices[k - 1].z;
    if (gap < 1e-3)
    {
      std::ostringstream os;
      os << "two slices of the DICOM series lie at the same position (" << slices[k].z
         << " mm along the slice normal): the series mixes acquisitions";
      error = os.str();
      return false;
    }
    report.minGap = std::min(report.minGap, gap);
    report.maxGap = std::max(report.maxGap, gap);
  }
  if (slices.size() < 2)
  {
    report.minGap = report.maxGap = sliceSpacing > 0.0 ? sliceSpacing : 1.0;
  }
  report.typicalGap = report.minGap;
  if (slices.size() >= 2)
  {
    std::vector<double> gaps;
    for (std::size_t k = 1; k < slices.size(); ++k)
      gaps.push_back(slices[k].z - slices[k - 1].z);
    std::nth_element(gaps.begin(), gaps.begin() + static_cast<std::ptrdiff_t>(gaps.size() / 2), gaps.end());
    report.typicalGap = gaps[gaps.size() / 2];
    for (std::size_t k = 1; k < slices.size(); ++k)
    {
      const double gap = slices[k].z - slices[k - 1].z;
      if (gap > 1.5 * report.typicalGap)
        report.wideGaps.push_back({ slices[k - 1].ipp, slices[k].ipp, gap, static_cast<int>(k) });
    }
  }
  const V3 origin = slices.front().ipp;
  if (slices.size() >= 2)
  {
    const V3 stack = sub(slices.back().ipp, origin);
    const double along = dot(stack, n);
    const double across = std::sqrt(std::max(0.0, dot(stack, stack) - along * along));
    report.gantryTiltDegrees = std::atan2(across, along) * 180.0 / M_PI;
  }

  // The output grid.
  // Automatic spacing: the largest spacing not above the smallest gap that
  // puts output slices exactly on the first and last input slices. A given
  // spacing is kept; the last output slice then lies at or beyond the last
  // input slice, and repeats it there.
  const double zSpan = slices.back().z - slices.front().z;
  const double wanted = sliceSpacing > 0.0 ? sliceSpacing : report.minGap;
  if (sliceSpacing > 0.0 && zSpan > 0.0 && sliceSpacing > zSpan * (1.0 + 1e-9))
  {
    // Two output slices, the second far beyond the series: a stretched
    // volume and a bone surface of the wrong size, not a resampling.
    std::ostringstream os;
    os << "a slice spacing of " << sliceSpacing << " mm is larger than the series' extent (" << zSpan
       << " mm from the first slice to the last): choose at most that";
    error = os.str();
    return false;
  }
  // Counted in double first: a spacing of 1e-9 mm made 1e11 steps, which
  // overflowed int into a volume of -2147483647 slices, with no error.
  const double stepCount = zSpan > 0.0 ? std::ceil(zSpan / wanted - 1e-9) : 0.0;
  if (!(stepCount < 1e6))
  {
    error = "the resampled volume would be too large; choose a larger slice spacing";
    return false;
  }
  const int steps = static_cast<int>(stepCount);
  const int nz = steps + 1;
  const double h = sliceSpacing > 0.0 || steps == 0 ? wanted : zSpan / steps;
  vtkNew<vtkImageCast> cast;
  cast->SetInputData(raw);
  cast->SetOutputScalarTypeToFloat();
  cast->Update();
  float* values = static_cast<float*>(cast->GetOutput()->GetScalarPointer());
  const vtkIdType sliceSize = static_cast<vtkIdType>(dims[0]) * dims[1];
  float background = std::numeric_limits<float>::max();
  for (vtkIdType i = 0; i < sliceSize * nslices; ++i)
  {
    values[i] += static_cast<float>(interceptAlone);
    background = std::min(background, values[i]);
  }
  report.lowestValue = background;
  const float* in = values;

  // In-plane offset of every slice, in pixels, relative to the first one.
  std::vector<double> shiftX(slices.size()), shiftY(slices.size()), zs(slices.size());
  for (std::size_t k = 0; k < slices.size(); ++k)
  {
    const V3 d = sub(slices[k].ipp, origin);
    shiftX[k] = dot(r, d) / dx;
    shiftY[k] = dot(c, d) / dy;
    zs[k] = slices[k].z - slices.front().z;
  }

  // The grid covers every slice's footprint: with tilt, later slices are
  // shifted in plane, and none of their pixels may fall off the grid.
  const int ox = static_cast<int>(std::floor(std::min(0.0, *std::min_element(shiftX.begin(), shiftX.end())) + 1e-6));
  const int oy = static_cast<int>(std::floor(std::min(0.0, *std::min_element(shiftY.begin(), shiftY.end())) + 1e-6));
  const int ex = static_cast<int>(std::ceil(std::max(0.0, *std::max_element(shiftX.begin(), shiftX.end())) - 1e-6));
  const int ey = static_cast<int>(std::ceil(std::max(0.0, *std::max_element(shiftY.begin(), shiftY.end())) - 1e-6));
  const int nx = dims[0] - ox + ex, ny = dims[1] - oy + ey;
  if (static_cast<double>(nz) * nx * ny > 2.0e9)
  {
    error = "the resampled volume would be too large; choose a larger slice spacing";
    return false;
  }

  output->Initialize();
  output->SetDimensions(nx, ny, nz);
  output->SetSpacing(dx, dy, h);
  output->SetOrigin(0.0, 0.0, 0.0);
  output->AllocateScalars(VTK_FLOAT, 1);
  float* out = static_cast<float*>(output->GetScalarPointer());
  output->GetPointData()->GetScalars()->SetName("ImageScalars");

  auto sample = [&](std::size_t k, double x, double y) -> double {
    // Bilinear value of slice k at pixel coordinates (x, y); background outside.
    if (x < 0.0 || y < 0.0 || x > dims[0] - 1 || y > dims[1] - 1)
    {
      return background;
    }
    const int i0 = std::min(static_cast<int>(x), dims[0] - 2 >= 0 ? dims[0] - 2 : 0);
    const int j0 = std::min(static_cast<int>(y), dims[1] - 2 >= 0 ? dims[1] - 2 : 0);
    const int i1 = std::min(i0 + 1, dims[0] - 1), j1 = std::min(j0 + 1, dims[1] - 1);
    const double fx = x - i0, fy = y - j0;
    const float* s = in + static_cast<vtkIdType>(slices[k].index) * sliceSize;
    const double v00 = s[j0 * dims[0] + i0], v10 = s[j0 * dims[0] + i1];
    const double v01 = s[j1 * dims[0] + i0], v11 = s[j1 * dims[0] + i1];
    return (1 - fy) * ((1 - fx) * v00 + fx * v10) + fy * ((1 - fx) * v01 + fx * v11);
  };

  vtkSMPTools::For(0, nz, [&](vtkIdType m0, vtkIdType m1) {
    for (vtkIdType m = m0; m < m1; ++m)
    {
      const double z = std::min(m * h, zSpan);
      std::size_t k = static_cast<std::size_t>(
        std::upper_bound(zs.begin(), zs.end(), z) - zs.begin());
      k = k == 0 ? 0 : k - 1;
      const std::size_t k1 = std::min(k + 1, zs.size() - 1);
      const double w = k1 == k ? 0.0 : (z - zs[k]) / (zs[k1] - zs[k]);
      float* o = out + m * static_cast<vtkIdType>(nx) * ny;
      for (int j = 0; j < ny; ++j)
      {
        for (int i = 0; i < nx; ++i)
        {
          // (x, y): pixel coordinates in the frame of the lowest slice.
          const double x = i + ox, y = j + oy;
          double v = sample(k, x - shiftX[k], y - shiftY[k]);
          if (w > 0.0)
          {
            v = (1.0 - w) * v + w * sample(k1, x - shiftX[k1], y - shiftY[k1]);
          }
          o[static_cast<vtkIdType>(j) * nx + i] = static_cast<float>(v);
        }
      }
    }
  });

  V3 corner; // the grid's first voxel: the lowest slice's, moved to cover every footprint
  for (std::size_t a = 0; a < 3; ++a)
    corner[a] = origin[a] + ox * dx * r[a] + oy * dy * c[a];
  setPatientMatrix(patientMatrix, frame, corner);
  return true;
}

bool readDICOMSegmentation(const DICOMSeriesInfo& series, vtkImageData* output, vtkMatrix4x4* patientMatrix,
  std::vector<Segment>& segments, std::string& error, vtkAlgorithm* progress)
{
  segments.clear();
  if (series.files.size() != 1)
  {
    error = "the DICOM segmentation (SEG) is in " + std::to_string(series.files.size()) +
      " files; one file, as segmentation tools write it, is read";
    return false;
  }
  // The frames in the file's order, each a slice (SortingOff): where each
  // lies and which segment it holds are read from its functional groups.
  vtkNew<CheckedDICOMReader> reader;
  reader->SortingOff();
  reader->AutoRescaleOff();
  if (!readFiles(reader, series.files, "segmentation", progress, 0.9, error))
    return false;
  vtkImageData* frames = reader->GetOutput();
  vtkDICOMMetaData* meta = reader->GetMetaData();
  int dims[3];
  frames->GetDimensions(dims);
  vtkDataArray* values = frames->GetPointData()->GetScalars();
  if (!values || frames->GetNumberOfScalarComponents() != 1 || dims[0] < 1 || dims[1] < 1)
  {
    error = "the DICOM segmentation holds no frames of one value per pixel";
    return false;
  }
  const int frameCount = dims[2];

  // Its segments, and how a pixel value says a frame's segment is there.
  const std::string type = meta->Get(DC::SegmentationType).AsString();
  if (type != "BINARY" && type != "FRACTIONAL" && type != "LABELMAP")
  {
    error = "the DICOM segmentation's SegmentationType is '" + type + "'; BINARY, FRACTIONAL or LABELMAP is read";
    return false;
  }
  const vtkDICOMValue& sequence = meta->Get(DC::SegmentSequence);
  const vtkDICOMItem* items = sequence.GetSequenceData();
  int largest = 0;
  for (unsigned int i = 0; items && i < sequence.GetNumberOfValues(); ++i)
  {
    Segment seg;
    seg.label = items[i].Get(DC::SegmentNumber).AsInt();
    seg.name = dicomText(items[i].Get(DC::SegmentLabel));
    if (seg.label < 1 || seg.label > 65535)
    {
      error = "a segment of the DICOM segmentation has the SegmentNumber " + std::to_string(seg.label);
      return false;
    }
    largest = std::max(largest, seg.label);
    segments.push_back(seg);
  }
  if (segments.empty())
  {
    error = "the DICOM segmentation lists no segments (SegmentSequence)";
    return false;
  }
  const double fractionalMax = meta->Get(DC::MaximumFractionalValue).IsValid()
    ? meta->Get(DC::MaximumFractionalValue).AsDouble()
    : 255.0;
  std::vector<int> frameSegment(static_cast<std::size_t>(frameCount), 0); // 0: LABELMAP, the value says
  const bool labelMap = type == "LABELMAP", binary = type == "BINARY";
  if (!labelMap)
  {
    for (int f = 0; f < frameCount; ++f)
    {
      const int number = meta->Get(0, f, DC::ReferencedSegmentNumber).AsInt();
      if (std::none_of(segments.begin(), segments.end(), [&](const Segment& seg) { return seg.label == number; }))
      {
        error = "frame " + std::to_string(f + 1) + " of the DICOM segmentation names segment " + std::to_string(number) +
          ", which its SegmentSequence does not list";
        return false;
      }
      frameSegment[static_cast<std::size_t>(f)] = number;
    }
  }
  // The segment number at pixel p of frame f, or 0. The frames are read as
  // unsigned char (BINARY, FRACTIONAL) or unsigned short (a LABELMAP of
  // more than 255 segments): read directly, a SEG of a hundred segments
  // has billions of pixels.
  const int scalarType = frames->GetScalarType();
  const void* pixels = frames->GetScalarPointer();
  auto segmentAt = [&](int f, vtkIdType p) -> int {
    const vtkIdType i = static_cast<vtkIdType>(f) * dims[0] * dims[1] + p;
    const double v = scalarType == VTK_UNSIGNED_CHAR ? static_cast<const unsigned char*>(pixels)[i]
      : scalarType == VTK_UNSIGNED_SHORT             ? static_cast<const unsigned short*>(pixels)[i]
                                                     : values->GetComponent(i, 0);
    if (labelMap)
      return v >= 1.0 && v <= largest ? static_cast<int>(v) : 0;
    const bool in = binary ? v != 0.0 : v >= 0.5 * fractionalMax;
    return in ? frameSegment[static_cast<std::size_t>(f)] : 0;
  };

  // The frames' grid.
  double iop[6], ps[2];
  const vtkDICOMValue& orientation = meta->Get(0, 0, DC::ImageOrientationPatient);
  const vtkDICOMValue& pixelSpacing = meta->Get(0, 0, DC::PixelSpacing);
  if (orientation.GetNumberOfValues() < 6 || pixelSpacing.GetNumberOfValues() < 2)
  {
    error = "the DICOM segmentation has no ImageOrientationPatient or PixelSpacing";
    return false;
  }
  orientation.GetValues(iop, 6);
  pixelSpacing.GetValues(ps, 2);
  SliceFrame frame;
  const double dx = ps[1], dy = ps[0]; // PixelSpacing is (row spacing, column spacing)
  if (!sliceFrame(iop, frame) || !(dx > 0.0) || !(dy > 0.0))
  {
    error = "the DICOM segmentation's ImageOrientationPatient or PixelSpacing is degenerate";
    return false;
  }
  const V3 &r = frame.r, &c = frame.c, &n = frame.n;
  std::vector<V3> positions(static_cast<std::size_t>(frameCount));
  std::vector<double> zs(static_cast<std::size_t>(frameCount));
  for (int f = 0; f < frameCount; ++f)
  {
    const vtkDICOMValue& p = meta->Get(0, f, DC::ImagePositionPatient);
    if (p.GetNumberOfValues() < 3)
    {
      error = "frame " + std::to_string(f + 1) + " of the DICOM segmentation has no ImagePositionPatient";
      return false;
    }
    double q[3], o[6];
    p.GetValues(q, 3);
    const vtkDICOMValue& frameOrientation = meta->Get(0, f, DC::ImageOrientationPatient);
    if (frameOrientation.GetNumberOfValues() >= 6)
    {
      frameOrientation.GetValues(o, 6);
      for (int i = 0; i < 6; ++i)
        if (std::abs(o[i] - iop[i]) > 1e-4)
        {
          error = "the frames of the DICOM segmentation do not share one ImageOrientationPatient";
          return false;
        }
    }
    positions[static_cast<std::size_t>(f)] = { q[0], q[1], q[2] };
    zs[static_cast<std::size_t>(f)] = dot(n, positions[static_cast<std::size_t>(f)]);
    const V3 d = sub(positions[static_cast<std::size_t>(f)], positions[0]);
    if (std::abs(dot(r, d)) > 0.01 * dx || std::abs(dot(c, d)) > 0.01 * dy)
    {
      error = "the frames of the DICOM segmentation are shifted against each other in their plane";
      return false;
    }
  }
  std::vector<double> levels = zs;
  std::sort(levels.begin(), levels.end());
  double h = meta->Get(0, 0, DC::SpacingBetweenSlices).AsDouble();
  if (!(h > 0.0))
  {
    h = 0.0;
    for (std::size_t k = 1; k < levels.size(); ++k)
      if (levels[k] - levels[k - 1] > 1e-3 && (h == 0.0 || levels[k] - levels[k - 1] < h))
        h = levels[k] - levels[k - 1];
    if (h == 0.0)
      h = meta->Get(0, 0, DC::SliceThickness).AsDouble() > 0.0 ? meta->Get(0, 0, DC::SliceThickness).AsDouble() : 1.0;
  }
  std::ostringstream spacingText; // "2 mm", not "2.000000 mm"
  spacingText << h << " mm";
  constexpr int kPad = 2; // empty slices beyond the first and last frame
  const double z0 = levels.front() - kPad * h;
  const double slicesSpanned = (levels.back() - levels.front()) / h;
  if (!(slicesSpanned < 1e5))
  {
    error = "the frames of the DICOM segmentation span too many slices of " + spacingText.str();
    return false;
  }
  const int nz = static_cast<int>(std::lround(slicesSpanned)) + 1 + 2 * kPad;
  std::vector<int> frameSlice(static_cast<std::size_t>(frameCount));
  for (int f = 0; f < frameCount; ++f)
  {
    const double at = (zs[static_cast<std::size_t>(f)] - z0) / h;
    if (std::abs(at - std::round(at)) > 0.01)
    {
      error = "the frames of the DICOM segmentation do not lie on a grid of " + spacingText.str() + " slices";
      return false;
    }
    frameSlice[static_cast<std::size_t>(f)] = static_cast<int>(std::lround(at));
  }

  // Layers: each segment goes to the first layer where it overlaps no other
  // (a LABELMAP's segments cannot overlap: one layer).
  const vtkIdType sliceSize = static_cast<vtkIdType>(dims[0]) * dims[1];
  const vtkIdType voxels = sliceSize * nz;
  std::vector<std::vector<unsigned short>> layers;
  for (Segment& seg : segments)
  {
    std::vector<int> own; // its frames
    for (int f = 0; f < frameCount; ++f)
      if (labelMap || frameSegment[static_cast<std::size_t>(f)] == seg.label)
        own.push_back(f);
    auto fits = [&](const std::vector<unsigned short>& layer) {
      for (int f : own)
      {
        const unsigned short* slice = layer.data() + frameSlice[static_cast<std::size_t>(f)] * sliceSize;
        for (vtkIdType p = 0; p < sliceSize; ++p)
          if (slice[p] != 0 && slice[p] != seg.label && segmentAt(f, p) == seg.label)
            return false;
      }
      return true;
    };
    const int l = layerFor(layers, voxels, [&](const std::vector<unsigned short>& layer) { return labelMap || fits(layer); });
    if (l < 0)
    {
      error = "the DICOM segmentation's segments overlap in more layers than fit in memory";
      return false;
    }
    seg.layer = l;
    for (int f : own)
    {
      unsigned short* slice = layers[static_cast<std::size_t>(l)].data() + frameSlice[static_cast<std::size_t>(f)] * sliceSize;
      for (vtkIdType p = 0; p < sliceSize; ++p)
        if (segmentAt(f, p) == seg.label)
          slice[p] = static_cast<unsigned short>(seg.label);
    }
  }

  const int gridDims[3] = { dims[0], dims[1], nz };
  const double spacing[3] = { dx, dy, h };
  setLayers(output, gridDims, spacing, layers, largest);

  V3 corner; // the first frame, moved along the normal down to the grid's first slice
  for (std::size_t a = 0; a < 3; ++a)
    corner[a] = positions[0][a] + (z0 - zs[0]) * n[a];
  setPatientMatrix(patientMatrix, frame, corner);
  return true;
}

int layerFor(std::vector<std::vector<unsigned short>>& layers, long long voxels,
  const std::function<bool(const std::vector<unsigned short>&)>& fits)
{
  for (std::size_t l = 0; l < layers.size(); ++l)
    if (fits(layers[l]))
      return static_cast<int>(l);
  if (static_cast<double>(voxels) * static_cast<double>(layers.size() + 1) > 2.0e9)
    return -1;
  layers.emplace_back(static_cast<std::size_t>(voxels), 0);
  return static_cast<int>(layers.size()) - 1;
}

void setLayers(vtkImageData* output, const int dims[3], const double spacing[3],
  const std::vector<std::vector<unsigned short>>& layers, int largestLabel)
{
  output->Initialize();
  output->SetDimensions(dims[0], dims[1], dims[2]);
  output->SetSpacing(spacing[0], spacing[1], spacing[2]);
  output->SetOrigin(0.0, 0.0, 0.0);
  const int components = static_cast<int>(layers.size());
  output->AllocateScalars(largestLabel <= 255 ? VTK_UNSIGNED_CHAR : VTK_UNSIGNED_SHORT, components);
  output->GetPointData()->GetScalars()->SetName("Segments");
  const vtkIdType voxels = static_cast<vtkIdType>(dims[0]) * dims[1] * dims[2];
  auto fill = [&](auto* out) {
    for (vtkIdType v = 0; v < voxels; ++v)
      for (int l = 0; l < components; ++l)
        out[v * components + l] =
          static_cast<std::remove_pointer_t<decltype(out)>>(layers[static_cast<std::size_t>(l)][static_cast<std::size_t>(v)]);
  };
  if (largestLabel <= 255)
    fill(static_cast<unsigned char*>(output->GetScalarPointer()));
  else
    fill(static_cast<unsigned short*>(output->GetScalarPointer()));
}

} // namespace lkvtk
