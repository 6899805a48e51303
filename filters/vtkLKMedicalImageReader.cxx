#include "vtkLKMedicalImageReader.h"

#include "vtkLKDICOMSeries.h"
#include "vtkLKProgressRelay.h"
#include "vtkLKMemory.h"

#include <vtkByteSwap.h>
#include <vtkCallbackCommand.h>
#include <vtkCharArray.h>
#include <vtkDataArray.h>
#include <vtkDirectory.h>
#include <vtkDoubleArray.h>
#include <vtkErrorCode.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkMatrix4x4.h>
#include <vtkMetaImageReader.h>
#include <vtkNIFTIImageHeader.h>
#include <vtkNIFTIImageReader.h>
#include <vtkNew.h>
#include <vtkNrrdReader.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkSMPTools.h>
#include <vtkStringArray.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtk_zlib.h>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <new>
#include <optional>
#include <sstream>
#include <vector>

#include <sys/stat.h>

vtkStandardNewMacro(vtkLKMedicalImageReader);

namespace
{

std::string lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char ch) { return std::tolower(ch); });
  return s;
}

bool endsWith(const std::string& s, const std::string& suffix)
{
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/// A file name (lower case) of a volume format the reader takes by extension.
bool isVolumeFileName(const std::string& name)
{
  for (const char* ext : { ".nrrd", ".nhdr", ".mha", ".mhd", ".nii", ".nii.gz" })
    if (endsWith(name, ext))
      return true;
  return false;
}

std::string trim(const std::string& s)
{
  const auto b = s.find_first_not_of(" \t\r\n");
  const auto e = s.find_last_not_of(" \t\r\n");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}

/// Text header fields "key: value" (NRRD) or "key = value" (MetaImage), up to
/// the first empty line (NRRD) or the ElementDataFile line (MetaImage).
/// `headerBytes`, when given, receives the header's length in bytes: where
/// data attached to the header starts. `keyValues`, when given, receives
/// NRRD's key/value pairs "key:=value", keys as written.
std::map<std::string, std::string> readHeader(const std::string& path, char separator, std::size_t* headerBytes = nullptr,
  std::map<std::string, std::string>* keyValues = nullptr)
{
  std::map<std::string, std::string> fields;
  std::ifstream in(path, std::ios::binary);
  std::string line;
  std::size_t bytes = 0;
  while (std::getline(in, line) && bytes < (1u << 20))
  {
    bytes += line.size() + 1;
    line = trim(line);
    if (line.empty())
    {
      break;
    }
    const auto pos = line.find(separator);
    if (pos == std::string::npos || line[0] == '#')
    {
      continue;
    }
    std::string key = lower(trim(line.substr(0, pos)));
    std::string value = trim(line.substr(pos + 1));
    if (separator == ':' && !value.empty() && value[0] == '=')
    {
      if (keyValues) // NRRD key/value pair "key:=value"
        (*keyValues)[trim(line.substr(0, pos))] = trim(value.substr(1));
      continue;
    }
    fields[key] = value;
    if (key == "elementdatafile")
    {
      break;
    }
  }
  if (headerBytes)
    *headerBytes = bytes;
  return fields;
}

using lkvtk::Segment;

/// A 3D Slicer segmentation's segments, from its NRRD header's key/value
/// pairs (readHeader's `keyValues`) "SegmentN_ID:=...", "SegmentN_Name:=...",
/// "SegmentN_LabelValue:=..." and "SegmentN_Layer:=..." (N from 0). As 3D
/// Slicer reads them: the name is the ID when not given, the label value 1,
/// and the layer N (Slicer 4.10 and older saved every segment in a layer of
/// its own, as a 0/1 map, without these two keys).
std::vector<Segment> nrrdSegments(const std::map<std::string, std::string>& pairs)
{
  // A whole number from min up, or nothing.
  auto whole = [](const std::string& text, long min) -> std::optional<int> {
    char* end = nullptr;
    const long v = std::strtol(text.c_str(), &end, 10);
    if (end == text.c_str() || v < min || v > std::numeric_limits<int>::max())
      return std::nullopt;
    return static_cast<int>(v);
  };
  std::vector<Segment> segments;
  for (int i = 0;; ++i)
  {
    const std::string key = "Segment" + std::to_string(i) + "_";
    const auto id = pairs.find(key + "ID");
    const auto name = pairs.find(key + "Name");
    if (id == pairs.end() && name == pairs.end())
      break;
    Segment seg;
    seg.name = name != pairs.end() ? name->second : id->second;
    seg.layer = i;
    const auto value = pairs.find(key + "LabelValue");
    const auto layer = pairs.find(key + "Layer");
    if (value != pairs.end())
    {
      const auto v = whole(value->second, 1);
      if (!v)
        break;
      seg.label = *v;
    }
    if (layer != pairs.end())
    {
      const auto l = whole(layer->second, 0);
      if (!l)
        break;
      seg.layer = *l;
    }
    segments.push_back(seg);
  }
  return segments;
}

std::vector<double> numbers(const std::string& text)
{
  std::string cleaned = text;
  for (char& ch : cleaned)
  {
    if (ch == '(' || ch == ')' || ch == ',')
    {
      ch = ' ';
    }
  }
  std::istringstream is(cleaned);
  std::vector<double> v;
  std::string token;
  while (is >> token)
  {
    if (token == "none")
    {
      continue;
    }
    char* end = nullptr;
    const double d = std::strtod(token.c_str(), &end);
    if (end && *end == '\0')
    {
      v.push_back(d);
    }
  }
  return v;
}

/// Bytes of one value of an NRRD "type" or a MetaImage "ElementType"; 0 for
/// a type this check does not know.
std::size_t valueBytes(const std::string& typeName)
{
  const std::string t = lower(typeName);
  static const std::map<std::string, std::size_t> sizes{ { "signed char", 1 }, { "int8", 1 }, { "int8_t", 1 },
    { "uchar", 1 }, { "unsigned char", 1 }, { "uint8", 1 }, { "uint8_t", 1 }, { "short", 2 }, { "short int", 2 },
    { "signed short", 2 }, { "signed short int", 2 }, { "int16", 2 }, { "int16_t", 2 }, { "ushort", 2 },
    { "unsigned short", 2 }, { "unsigned short int", 2 }, { "uint16", 2 }, { "uint16_t", 2 }, { "int", 4 },
    { "signed int", 4 }, { "int32", 4 }, { "int32_t", 4 }, { "uint", 4 }, { "unsigned int", 4 }, { "uint32", 4 },
    { "uint32_t", 4 }, { "longlong", 8 }, { "long long", 8 }, { "long long int", 8 }, { "signed long long", 8 },
    { "signed long long int", 8 }, { "int64", 8 }, { "int64_t", 8 }, { "ulonglong", 8 }, { "unsigned long long", 8 },
    { "unsigned long long int", 8 }, { "uint64", 8 }, { "uint64_t", 8 }, { "float", 4 }, { "double", 8 },
    { "met_char", 1 }, { "met_uchar", 1 }, { "met_short", 2 }, { "met_ushort", 2 }, { "met_int", 4 },
    { "met_uint", 4 }, { "met_long_long", 8 }, { "met_ulong_long", 8 }, { "met_float", 4 }, { "met_double", 8 } };
  const auto it = sizes.find(t);
  return it == sizes.end() ? 0 : it->second;
}

/// Empty, or why the uncompressed voxel data of an NRRD (`nrrd`) or
/// MetaImage file is shorter than its header `h` (readHeader, `headerBytes`
/// long) asks. vtkNrrdReader only warns
/// of such a file and vtkMetaImageReader only prints to the terminal; both
/// return a volume whose missing voxels are zero or stale. Compressed data
/// (which their readers check), data in several files and headers this check
/// does not understand are left to the readers.
std::string truncatedRawData(
  const std::string& path, const std::map<std::string, std::string>& h, std::size_t headerBytes, bool nrrd)
{
  auto field = [&](std::initializer_list<const char*> keys) {
    for (const char* k : keys)
      if (h.count(k))
        return h.at(k);
    return std::string();
  };
  const std::string encoding = lower(field({ "encoding" }));
  if (nrrd ? encoding != "raw" : lower(field({ "compresseddata" })) == "true")
    return {};
  if (nrrd && !field({ "line skip", "lineskip" }).empty() && numbers(field({ "line skip", "lineskip" })) != std::vector<double>{ 0 })
    return {};
  const std::size_t bytesPerValue = valueBytes(field({ nrrd ? "type" : "elementtype" }));
  const std::vector<double> sizes = numbers(field({ nrrd ? "sizes" : "dimsize" }));
  if (bytesPerValue == 0 || sizes.empty())
    return {};
  double needed = static_cast<double>(bytesPerValue);
  for (double n : sizes)
    needed *= n;
  if (!nrrd)
  {
    const auto channels = numbers(field({ "elementnumberofchannels" }));
    needed *= channels.size() == 1 && channels[0] >= 1 ? channels[0] : 1.0;
  }
  // Where the data is: after the header, or in a file the header names.
  std::string dataFile = field(nrrd ? std::initializer_list<const char*>{ "data file", "datafile" }
                                    : std::initializer_list<const char*>{ "elementdatafile" });
  double offset = 0;
  if (dataFile.empty() || (!nrrd && lower(dataFile) == "local"))
  {
    if (nrrd && endsWith(lower(path), ".nhdr"))
      return {};
    dataFile = path;
    offset = static_cast<double>(headerBytes);
  }
  else
  {
    if (dataFile.find_first_of(" %") != std::string::npos || lower(dataFile) == "list")
      return {}; // several files
    const std::string folder = vtksys::SystemTools::GetFilenamePath(path);
    if (dataFile[0] != '/' && !folder.empty())
      dataFile = folder + "/" + dataFile;
  }
  const std::vector<double> skip = numbers(field({ nrrd ? "byte skip" : "headersize", nrrd ? "byteskip" : "headersize" }));
  if (!skip.empty())
  {
    if (skip[0] < 0)
      return {}; // "-1": the data is at the end of the file, however long the rest
    offset += skip[0];
  }
  if (!vtksys::SystemTools::FileExists(dataFile, true))
    return {}; // the reader names the missing file
  const double available = static_cast<double>(vtksys::SystemTools::FileLength(dataFile)) - offset;
  if (available >= needed)
    return {};
  std::ostringstream why;
  why.precision(15);
  why << "its voxel data has " << std::max(available, 0.0) << " bytes where the header asks for " << needed
      << ": the file is truncated";
  return why.str();
}

/// Builds data->patient from unit axis directions, spacing and origin; returns
/// the spacings (the lengths of the given axis vectors).
void matrixFromAxes(const std::vector<double>& axes, const std::vector<double>& origin, bool ras,
  vtkMatrix4x4* m, double spacing[3])
{
  m->Identity();
  const double flip[3] = { ras ? -1.0 : 1.0, ras ? -1.0 : 1.0, 1.0 };
  for (int a = 0; a < 3; ++a)
  {
    const double len =
      std::sqrt(axes[3 * a] * axes[3 * a] + axes[3 * a + 1] * axes[3 * a + 1] + axes[3 * a + 2] * axes[3 * a + 2]);
    spacing[a] = len;
    for (int row = 0; row < 3; ++row)
    {
      m->SetElement(row, a, flip[row] * axes[3 * a + row] / len);
    }
  }
  for (int row = 0; row < 3; ++row)
  {
    m->SetElement(row, 3, flip[row] * (origin.size() == 3 ? origin[row] : 0.0));
  }
}

/// The text of a VTK error event's message, without the "ERROR: In FILE,
/// line N" line and the "vtkClass (0x...): " before it.
std::string messageText(const std::string& event)
{
  std::string m = event;
  if (m.rfind("ERROR: In", 0) == 0)
  {
    const auto nl = m.find('\n');
    m = nl == std::string::npos ? std::string() : m.substr(nl + 1);
  }
  const auto colon = m.find("): ");
  if (colon != std::string::npos && colon < 80 && m.rfind("vtk", 0) == 0)
    m = m.substr(colon + 3);
  return trim(m);
}

/// The RT structure sets beside a CT that was read, and how to read one:
/// the last `beside` of them lie in folders beside the CT's.
std::string structureSetsNote(
  const std::vector<lkvtk::StructureSetInfo>& sets, const std::string& seriesUID, std::size_t beside)
{
  std::ostringstream os;
  const std::string what =
    sets.size() == 1 ? std::string("an RT structure set") : std::to_string(sets.size()) + " RT structure sets";
  if (beside == 0)
    os << "The folder also holds " << what;
  else if (beside == sets.size())
    os << (beside == 1 ? "A folder beside the CT's holds " : "The folders beside the CT's hold ") << what;
  else
    os << "The folder and the folders beside the CT's hold " << what;
  os << " (organs contoured for radiotherapy); give its file to read its ROIs as segments (latticekit-surface "
        "and the planner do when --label names one of them):";
  for (const auto& set : sets)
  {
    os << "\n  '" << set.file << "'" << (set.drawnOn(seriesUID) ? ", drawn on this series" : "") << ": ";
    for (std::size_t i = 0; i < set.roiNames.size() && i < 8; ++i)
      os << (i ? ", '" : "'") << set.roiNames[i] << "'";
    if (set.roiNames.size() > 8)
      os << " and " << set.roiNames.size() - 8 << " more";
    if (set.roiNames.empty())
      os << "no ROIs";
  }
  return os.str();
}

/// The warning for a DICOM series whose slices are not evenly spaced (3D
/// Slicer warns of unequal spacing too): a slice lost on the way from the
/// scanner leaves a gap the resampling fills by interpolation.
std::string wideGapsWarning(const lkvtk::DICOMGeometryReport& report)
{
  auto fixed = [](double v, int digits) {
    std::ostringstream os;
    os.setf(std::ios::fixed);
    os.precision(digits);
    os << v;
    return os.str();
  };
  auto at = [&](const std::array<double, 3>& p) {
    return "(" + fixed(p[0], 1) + ", " + fixed(p[1], 1) + ", " + fixed(p[2], 1) + ")";
  };
  // Consecutive wide gaps are one run (a stretch scanned at a coarser
  // spacing); a single one between regular slices looks like a lost slice.
  const std::size_t n = report.wideGaps.size();
  std::vector<std::string> runs;
  int missing = 0;
  for (std::size_t g = 0; g < n;)
  {
    std::size_t end = g + 1;
    while (end < n && report.wideGaps[end].afterIndex == report.wideGaps[end - 1].afterIndex + 1)
      ++end;
    double lo = report.wideGaps[g].gap, hi = lo;
    for (std::size_t k = g; k < end; ++k)
    {
      const double gap = report.wideGaps[k].gap;
      lo = std::min(lo, gap);
      hi = std::max(hi, gap);
      const double ratio = gap / report.typicalGap;
      const long whole = std::lround(ratio);
      if (std::abs(ratio - static_cast<double>(whole)) < 0.1)
        missing += static_cast<int>(whole) - 1; // a gap of k typical ones: k - 1 slices
    }
    const std::string sizes = fixed(lo, 2) + (hi - lo >= 0.005 ? " to " + fixed(hi, 2) : std::string()) + " mm";
    runs.push_back(end - g == 1
        ? sizes + " between the slices at " + at(report.wideGaps[g].before) + " and " + at(report.wideGaps[g].after)
        : std::to_string(end - g) + " gaps of " + sizes + " from the slice at " + at(report.wideGaps[g].before) +
          " to the one at " + at(report.wideGaps[end - 1].after));
    g = end;
  }
  std::string listed;
  for (std::size_t r = 0; r < runs.size() && r < 3; ++r)
    listed += (r ? "; " : "") + runs[r];
  if (runs.size() > 3)
    listed += "; and " + std::to_string(runs.size() - 3) + " more places";
  return "The slices are not evenly spaced: most lie " + fixed(report.typicalGap, 2) + " mm apart, but " +
    std::to_string(n) + (n == 1 ? " gap is" : " gaps are") + " wider (" + listed + ")" +
    (missing > 0 ? ", as if " + std::to_string(missing) + (missing == 1 ? " slice were missing" : " slices were missing")
                 : std::string()) +
    ". The volume is interpolated across them: check that the series is complete before planning on it.";
}

/// vtkNrrdReader that reads a 4D NRRD whose first axis is a list, as 3D
/// Slicer saves a segmentation whose segments overlap (one label map per
/// layer, gzip-compressed). Two mends to VTK 9.1's reader:
/// - It takes a "space" field to mean three axes, so where "space" follows
///   "dimension: 4" (as 3D Slicer, ITK and teem write them) it reads three of
///   the four sizes, and the layers of a volume come out as a 2D image.
///   Moved before "dimension", "space" no longer overrides it.
/// - Its gzip reading of several values per voxel fills only part of the
///   volume (the layers of tests/data/overlapping_segments.seg.nrrd came out
///   with 419 of a ball's 1,031 voxels, without an error; the same file
///   uncompressed reads right). The whole stream is read here.
/// Made with its own New(), it also escapes the object factory, which in
/// Debian's VTK may hand out an MPI variant of vtkNrrdReader that reads
/// nothing.
class SpaceFirstNrrdReader : public vtkNrrdReader
{
public:
  static SpaceFirstNrrdReader* New();
  vtkTypeMacro(SpaceFirstNrrdReader, vtkNrrdReader);

protected:
  SpaceFirstNrrdReader() = default;

  int ReadHeader(vtkCharArray* headerBuffer) override
  {
    // The buffer holds the header and a terminating zero; the line moves
    // within it, so its length (the header's size) is kept.
    const vtkIdType size = headerBuffer->GetNumberOfTuples() - 1;
    if (size > 0)
    {
      std::string text(headerBuffer->GetPointer(0), static_cast<std::size_t>(size));
      const std::size_t firstLineEnd = text.find('\n');
      const std::size_t space = text.find("\nspace: ");
      const std::size_t spaceEnd = space == std::string::npos ? space : text.find('\n', space + 1);
      if (firstLineEnd != std::string::npos && spaceEnd != std::string::npos && space > firstLineEnd)
      {
        const std::string line = text.substr(space + 1, spaceEnd - space);
        text.erase(space + 1, spaceEnd - space);
        text.insert(firstLineEnd + 1, line);
        std::copy(text.begin(), text.end(), headerBuffer->GetPointer(0));
      }
    }
    return this->Superclass::ReadHeader(headerBuffer);
  }

  int ReadDataGZip(vtkImageData* output) override
  {
    if (output->GetNumberOfScalarComponents() == 1 || this->GetFileNames())
      return this->Superclass::ReadDataGZip(output);
    const std::size_t bytes = static_cast<std::size_t>(output->GetNumberOfPoints()) *
      static_cast<std::size_t>(output->GetNumberOfScalarComponents()) * static_cast<std::size_t>(output->GetScalarSize());
    std::ifstream file(this->GetFileName(), std::ios::binary);
    file.seekg(static_cast<std::streamoff>(this->GetHeaderSize()));
    std::vector<unsigned char> compressed((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    if (!file.eof() && file.fail())
    {
      vtkErrorMacro("Cannot read the gzip data of " << this->GetFileName() << ".");
      return 0;
    }
    z_stream stream{};
    if (inflateInit2(&stream, 15 + 32) != Z_OK) // a gzip or zlib header
    {
      vtkErrorMacro("Cannot start zlib.");
      return 0;
    }
    auto* out = static_cast<unsigned char*>(output->GetScalarPointer());
    std::size_t in = 0, done = 0;
    int status = Z_OK;
    while (status == Z_OK && done < bytes)
    {
      // zlib counts in 32 bits: at most 1 GiB in and out per call.
      const std::size_t inChunk = std::min<std::size_t>(compressed.size() - in, std::size_t(1) << 30);
      const std::size_t outChunk = std::min<std::size_t>(bytes - done, std::size_t(1) << 30);
      stream.next_in = compressed.data() + in;
      stream.avail_in = static_cast<uInt>(inChunk);
      stream.next_out = out + done;
      stream.avail_out = static_cast<uInt>(outChunk);
      status = inflate(&stream, Z_NO_FLUSH);
      in += inChunk - stream.avail_in;
      done += outChunk - stream.avail_out;
      if (status == Z_BUF_ERROR && stream.avail_in == 0 && in < compressed.size())
        status = Z_OK; // more input to give
    }
    inflateEnd(&stream);
    if (done < bytes)
    {
      vtkErrorMacro("The gzip data of " << this->GetFileName() << " holds " << done << " of the " << bytes
                                        << " bytes its header asks for: the file is truncated or damaged.");
      this->SetErrorCode(vtkErrorCode::PrematureEndOfFileError);
      return 0;
    }
    if (this->GetSwapBytes() && output->GetScalarSize() > 1)
      vtkByteSwap::SwapVoidRange(out, static_cast<vtkIdType>(bytes / output->GetScalarSize()), output->GetScalarSize());
    return 1;
  }
};
vtkStandardNewMacro(SpaceFirstNrrdReader);

struct ErrorFlag
{
  bool failed = false;
  std::string message;
  vtkNew<vtkCallbackCommand> command;
  explicit ErrorFlag(vtkObject* o)
  {
    command->SetClientData(this);
    command->SetCallback([](vtkObject*, unsigned long, void* cd, void* call) {
      auto* self = static_cast<ErrorFlag*>(cd);
      self->failed = true;
      if (call)
      {
        self->message = messageText(static_cast<const char*>(call));
      }
    });
    o->AddObserver(vtkCommand::ErrorEvent, command);
  }
};

/// Reads the image of an image reader: the header first, and the voxels only
/// when the header describes a volume (at least 2 voxels along each axis;
/// vtkNrrdReader crashes reading a 2-D raw file) that fits in this machine's
/// memory (a corrupt or hostile header asks for terabytes, and the allocation
/// ended the program) and when `dataProblem` (the file's own check, such as
/// truncatedRawData) is empty. `message` says why not. The voxels' reading
/// is `owner`'s progress.
bool readImage(vtkAlgorithm* owner, vtkImageReader2* reader, ErrorFlag& flag, std::string& message,
  const std::string& dataProblem = {})
{
  reader->UpdateInformation();
  if (flag.failed)
  {
    message = flag.message;
    return false;
  }
  int extent[6] = { 0, -1, 0, -1, 0, -1 };
  vtkInformation* info = reader->GetOutputInformation(0);
  if (!info || !info->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    message = "the header gives no image extent";
    return false;
  }
  info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  double voxels = 1.0;
  std::ostringstream size;
  for (int a = 0; a < 3; ++a)
  {
    const double n = static_cast<double>(extent[2 * a + 1]) - extent[2 * a] + 1.0;
    size << (a ? " x " : "") << (n > 0 ? n : 0.0);
    voxels *= n > 0 ? n : 0.0;
  }
  for (int a = 0; a < 3; ++a)
  {
    if (extent[2 * a + 1] - extent[2 * a] + 1 < 2)
    {
      message = "the image has " + size.str() + " voxels; a volume needs at least 2 along each axis";
      return false;
    }
  }
  const int components = std::max(1, reader->GetNumberOfScalarComponents());
  const int typeSize = std::max(1, vtkDataArray::GetDataTypeSize(reader->GetDataScalarType()));
  const double bytes = voxels * components * typeSize;
  std::string tooLarge;
  if (lkvtk::exceedsMemory(bytes, tooLarge))
  {
    message = "the header describes " + size.str() + " voxels (" + tooLarge + ")";
    return false;
  }
  if (!dataProblem.empty())
  {
    message = dataProblem;
    return false;
  }
  try
  {
    lkvtk::ProgressRelay progress(owner, reader, 0.0, 1.0);
    reader->Update();
  }
  catch (const std::bad_alloc&)
  {
    message = "out of memory reading " + size.str() + " voxels";
    return false;
  }
  if (flag.failed || !reader->GetOutput() || reader->GetOutput()->GetNumberOfPoints() == 0)
  {
    message = flag.message;
    return false;
  }
  return true;
}

} // namespace

vtkLKMedicalImageReader::vtkLKMedicalImageReader()
{
  this->SetNumberOfInputPorts(0);
  this->PatientMatrix = vtkMatrix4x4::New();
  this->Volume = vtkImageData::New();
}

vtkLKMedicalImageReader::~vtkLKMedicalImageReader()
{
  this->SetFileName(nullptr);
  this->PatientMatrix->Delete();
  this->Volume->Delete();
}

void vtkLKMedicalImageReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "SeriesIndex: " << this->SeriesIndex << "\n";
  os << indent << "SliceSpacing: " << this->SliceSpacing << "\n";
  os << indent << "FileFormat: " << this->FileFormat << "\n";
  os << indent << "ReferenceImageFileName: " << this->ReferenceImageFileName << "\n";
  os << indent << "NumberOfSegments: " << this->GetNumberOfSegments() << "\n";
  os << indent << "NumberOfStructureSets: " << this->GetNumberOfStructureSets() << "\n";
}

namespace
{
/// v = u slope + intercept over every voxel, computed in double: in a short
/// when the stored values are whole numbers, slope and intercept too, and
/// the values fit (a CT's HU), in an int when they fit that, else in a float.
vtkSmartPointer<vtkImageData> calibrated(vtkImageData* image, double slope, double intercept)
{
  vtkDataArray* in = image->GetPointData()->GetScalars();
  auto out = vtkSmartPointer<vtkImageData>::New();
  out->CopyStructure(image);
  if (!in)
    return out;
  double range[2];
  in->GetRange(range, 0);
  const double a = range[0] * slope + intercept, b = range[1] * slope + intercept;
  const double lo = std::min(a, b), hi = std::max(a, b);
  const bool whole = in->GetDataType() != VTK_FLOAT && in->GetDataType() != VTK_DOUBLE &&
    slope == std::round(slope) && intercept == std::round(intercept);
  int type = VTK_FLOAT;
  if (whole && lo >= VTK_SHORT_MIN && hi <= VTK_SHORT_MAX)
    type = VTK_SHORT;
  else if (whole && lo >= VTK_INT_MIN && hi <= VTK_INT_MAX)
    type = VTK_INT;
  vtkSmartPointer<vtkDataArray> values = vtkSmartPointer<vtkDataArray>::Take(vtkDataArray::CreateDataArray(type));
  values->SetName(in->GetName());
  values->SetNumberOfComponents(in->GetNumberOfComponents());
  values->SetNumberOfTuples(in->GetNumberOfTuples());
  // Whole numbers in, whole slope and intercept: the integer result is exact.
  const int components = in->GetNumberOfComponents();
  vtkSMPTools::For(0, in->GetNumberOfTuples(), [&](vtkIdType begin, vtkIdType end) {
    for (vtkIdType t = begin; t < end; ++t)
      for (int c = 0; c < components; ++c)
        values->SetComponent(t, c, in->GetComponent(t, c) * slope + intercept);
  });
  out->GetPointData()->SetScalars(values);
  return out;
}
} // namespace

bool vtkLKMedicalImageReader::ReadVolume()
{
  this->Volume->Initialize();
  this->PatientMatrix->Identity();
  this->FileFormat.clear();
  this->ReferenceImageFileName.clear();
  this->StructureSetFiles.clear();
  this->StructureSetROINames.clear();
  this->NumberOfSeries = 0;
  this->GantryTilt = this->MinimumSliceGap = this->MaximumSliceGap = 0.0;
  this->NumberOfInputSlices = 0;
  this->OrientationKnown = false;
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No FileName given.");
    return false;
  }
  const std::string path = this->FileName;
  if (!vtksys::SystemTools::FileExists(path))
  {
    vtkErrorMacro("Cannot open '" << path << "': no such file or folder.");
    return false;
  }
  // A pipe or a device: reading one waits for a writer, or for ever
  // (/dev/zero), and the readers seek in their files.
  struct stat info;
  if (stat(path.c_str(), &info) == 0 && !S_ISREG(info.st_mode) && !S_ISDIR(info.st_mode))
  {
    vtkErrorMacro("Cannot read '" << path << "': it is not a file or a folder but a "
                                  << (S_ISFIFO(info.st_mode) ? "pipe" : "device")
                                  << "; the volume must be a file (or a DICOM folder) to be read.");
    return false;
  }
  // A CD's DICOMDIR, as viewers open one: its folder, which the DICOMDIR
  // indexes, is read.
  const bool dicomdir = lower(vtksys::SystemTools::GetFilenameName(path)) == "dicomdir";
  const std::string name = lower(path);
  const bool isFolder = dicomdir || vtksys::SystemTools::FileIsDirectory(path);
  double spacing[3] = { 1, 1, 1 };
  vtkSmartPointer<vtkImageData> image;
  std::vector<Segment> segments; // a segmentation's: a .seg.nrrd's header, a DICOM SEG's
  std::string reference; // a file of the DICOM image series the volume belongs to
  std::vector<std::string> structureSets; // the RT structure sets drawn on it, and their ROIs
  std::vector<std::vector<std::string>> structureSetROIs;

  if (endsWith(name, ".nrrd") || endsWith(name, ".nhdr"))
  {
    this->FileFormat = "NRRD";
    vtkNew<SpaceFirstNrrdReader> reader;
    ErrorFlag flag(reader);
    reader->SetFileName(path.c_str());
    std::size_t headerBytes = 0;
    std::map<std::string, std::string> keyValues;
    const auto header = readHeader(path, ':', &headerBytes, &keyValues);
    // vtkNrrdReader takes the first of four axes as the values of a voxel
    // (3D Slicer's layers, a vector's components), whatever the file says,
    // and of five or more it reads part: a fourth axis that is not first
    // (time after space) would be read as scrambled voxels.
    const std::vector<double> axes = header.count("dimension") ? numbers(header.at("dimension")) : std::vector<double>{};
    if (axes.size() == 1 && axes[0] >= 4)
    {
      const std::vector<double> sizes = header.count("sizes") ? numbers(header.at("sizes")) : std::vector<double>{};
      std::string first;
      if (header.count("kinds"))
        std::istringstream(lower(header.at("kinds"))) >> first;
      const bool listFirst = header.count("kinds") ? first != "domain" && first != "space" && first != "time"
                                                   : !sizes.empty() && sizes[0] <= 9; // VTK's own guess
      if (axes[0] > 4 || !listFirst)
      {
        vtkErrorMacro("Cannot read NRRD file '" << path << "': it has " << axes[0] << " axes ("
                                                << (header.count("kinds") ? "kinds: " + header.at("kinds")
                                                                          : "sizes: " + header.at("sizes"))
                                                << ") and only a 3D volume, with a list of values per voxel "
                                                   "first where there are 4, is read.");
        return false;
      }
    }
    std::string message;
    if (!readImage(this, reader, flag, message, truncatedRawData(path, header, headerBytes, true)))
    {
      vtkErrorMacro("Cannot read NRRD file '" << path << "'" << (message.empty() ? "" : ": ") << message);
      return false;
    }
    image = reader->GetOutput();
    segments = nrrdSegments(keyValues);
    auto dirs = header.find("space directions");
    if (dirs != header.end() && numbers(dirs->second).size() >= 9)
    {
      const auto space = header.count("space") ? lower(header.at("space")) : std::string("left-posterior-superior");
      const bool ras = space.find("right") == 0 || space == "ras" || space == "ras-time";
      std::vector<double> origin;
      if (header.count("space origin"))
      {
        origin = numbers(header.at("space origin"));
      }
      std::vector<double> axes = numbers(dirs->second);
      axes.resize(9);
      matrixFromAxes(axes, origin, ras, this->PatientMatrix, spacing);
      // Directions in a space the header names are patient axes; without a
      // "space" field (only "space dimension") they are not anatomical.
      this->OrientationKnown = header.count("space") > 0;
    }
    else
    {
      image->GetSpacing(spacing);
      double o[3];
      image->GetOrigin(o);
      for (int row = 0; row < 3; ++row)
      {
        this->PatientMatrix->SetElement(row, 3, o[row]);
      }
    }
  }
  else if (endsWith(name, ".mha") || endsWith(name, ".mhd"))
  {
    this->FileFormat = "MetaImage";
    vtkNew<vtkMetaImageReader> reader;
    ErrorFlag flag(reader);
    reader->SetFileName(path.c_str());
    std::size_t headerBytes = 0;
    const auto header = readHeader(path, '=', &headerBytes);
    std::string message;
    if (!readImage(this, reader, flag, message, truncatedRawData(path, header, headerBytes, false)))
    {
      vtkErrorMacro("Cannot read MetaImage file '" << path << "'" << (message.empty() ? "" : ": ") << message);
      return false;
    }
    image = reader->GetOutput();
    image->GetSpacing(spacing);
    std::vector<double> axes = { 1, 0, 0, 0, 1, 0, 0, 0, 1 };
    for (const char* key : { "transformmatrix", "orientation", "rotation" })
    {
      if (header.count(key) && numbers(header.at(key)).size() == 9)
      {
        axes = numbers(header.at(key));
        break;
      }
    }
    for (int a = 0; a < 3; ++a)
    {
      for (int k = 0; k < 3; ++k)
      {
        axes[3 * a + k] *= spacing[a];
      }
    }
    std::vector<double> origin(3, 0.0);
    for (const char* key : { "offset", "position", "origin" })
    {
      if (header.count(key) && numbers(header.at(key)).size() == 3)
      {
        origin = numbers(header.at(key));
        break;
      }
    }
    matrixFromAxes(axes, origin, false, this->PatientMatrix, spacing);
    this->OrientationKnown = true; // MetaImage is LPS, identity axes by default (as ITK writes it)
  }
  else if (endsWith(name, ".nii") || endsWith(name, ".nii.gz") || endsWith(name, ".hdr") ||
    endsWith(name, ".img") || endsWith(name, ".img.gz"))
  {
    this->FileFormat = "NIfTI";
    vtkNew<vtkNIFTIImageReader> reader;
    ErrorFlag flag(reader);
    reader->SetFileName(path.c_str());
    std::string message;
    if (!readImage(this, reader, flag, message))
    {
      vtkErrorMacro("Cannot read NIfTI file '" << path << "'" << (message.empty() ? "" : ": ") << message);
      return false;
    }
    image = reader->GetOutput();
    // scl_slope and scl_inter calibrate the stored values (NIfTI-1: v = u
    // scl_slope + scl_inter unless scl_slope is 0). dcm2niix keeps a CT's
    // stored values and puts its RescaleIntercept here (often -1024):
    // without it the bone threshold would fall in soft tissue. vtkNIFTIImageReader
    // only reports them.
    const double slope = reader->GetRescaleSlope(), intercept = reader->GetRescaleIntercept();
    if (!std::isfinite(slope) || !std::isfinite(intercept))
    {
      vtkWarningMacro("'" << path << "' has a scl_slope or scl_inter that is not a number (" << slope << ", "
                          << intercept << "): its values are used as stored.");
    }
    else if (slope != 0.0 && (slope != 1.0 || intercept != 0.0))
    {
      image = calibrated(image, slope, intercept);
    }
    image->GetSpacing(spacing);
    double o[3];
    image->GetOrigin(o);
    vtkMatrix4x4* form = nullptr;
    if (reader->GetNIFTIHeader()->GetQFormCode() > 0 && reader->GetQFormMatrix())
    {
      form = reader->GetQFormMatrix();
    }
    else if (reader->GetNIFTIHeader()->GetSFormCode() > 0 && reader->GetSFormMatrix())
    {
      form = reader->GetSFormMatrix();
    }
    if (form == reader->GetQFormMatrix() && reader->GetNIFTIHeader()->GetSFormCode() > 0 &&
      reader->GetSFormMatrix())
    {
      // Both forms, and the qform is used. A registered image often keeps
      // the scanner's qform and the target space's sform, and tools that take
      // the sform place it elsewhere: say how far apart the two put it.
      int d[3];
      image->GetDimensions(d);
      double apart = 0.0;
      for (int corner = 0; corner < 8; ++corner)
      {
        double p[4] = { o[0] + ((corner & 1) ? (d[0] - 1) * spacing[0] : 0.0),
          o[1] + ((corner & 2) ? (d[1] - 1) * spacing[1] : 0.0), o[2] + ((corner & 4) ? (d[2] - 1) * spacing[2] : 0.0),
          1.0 };
        double q[4], sf[4];
        reader->GetQFormMatrix()->MultiplyPoint(p, q);
        reader->GetSFormMatrix()->MultiplyPoint(p, sf);
        apart = std::max(apart, std::sqrt((q[0] - sf[0]) * (q[0] - sf[0]) + (q[1] - sf[1]) * (q[1] - sf[1]) +
                                          (q[2] - sf[2]) * (q[2] - sf[2])));
      }
      if (apart > std::max(0.1, 0.1 * std::min({ spacing[0], spacing[1], spacing[2] })))
        vtkWarningMacro("'" << path << "' has a qform and an sform that place the volume up to " << apart
                            << " mm apart (qform_code " << reader->GetNIFTIHeader()->GetQFormCode() << ", sform_code "
                            << reader->GetNIFTIHeader()->GetSFormCode()
                            << "): the qform is used. Tools that take the sform (nibabel, for one) place it "
                               "elsewhere; check which space the plan is meant in.");
    }
    vtkNew<vtkMatrix4x4> ras2lps;
    ras2lps->SetElement(0, 0, -1.0);
    ras2lps->SetElement(1, 1, -1.0);
    vtkNew<vtkMatrix4x4> shift; // fold the reader's origin into the matrix
    for (int row = 0; row < 3; ++row)
    {
      shift->SetElement(row, 3, o[row]);
    }
    vtkNew<vtkMatrix4x4> tmp;
    if (form)
    {
      vtkMatrix4x4::Multiply4x4(form, shift, tmp);
    }
    else
    {
      tmp->DeepCopy(shift);
    }
    if (form)
    {
      vtkMatrix4x4::Multiply4x4(ras2lps, tmp, this->PatientMatrix);
      this->OrientationKnown = true;
    }
    else
    {
      // NIfTI "method 1": without qform or sform the orientation is unknown,
      // so no RAS->LPS flip is applied: data coordinates are kept.
      this->PatientMatrix->DeepCopy(tmp);
      vtkWarningMacro("'" << path << "' has neither a qform nor an sform: the patient "
                          << "orientation is unknown, so data coordinates are used as they are.");
    }
  }
  else if (!isFolder && lkvtk::isDICOMStructureSet(path))
  {
    // An RT structure set: its ROIs' contours filled into a label volume, on
    // the pixel lattice of the CT they were drawn on when it lies beside them.
    this->FileFormat = "DICOM RTSTRUCT";
    const std::string folder = vtksys::SystemTools::GetFilenamePath(path);
    std::vector<lkvtk::DICOMSeriesInfo> series;
    std::string error;
    // No image beside it is no error: the contours make a grid of their own.
    lkvtk::findDICOMSeries(folder.empty() ? "." : folder, series, error, this, 1);
    vtkNew<vtkImageData> volume;
    std::vector<std::string> notes;
    if (!lkvtk::readDICOMStructureSet(
          path, series, volume, this->PatientMatrix, segments, notes, reference, error, this))
    {
      vtkErrorMacro("Cannot read '" << path << "': " << error << ".");
      return false;
    }
    for (const std::string& note : notes)
      vtkWarningMacro("'" << path << "': " << note << ".");
    this->OrientationKnown = true;
    image = volume;
    image->GetSpacing(spacing);
  }
  else
  {
    this->FileFormat = "DICOM";
    if (std::isnan(this->SliceSpacing)) // SetSliceSpacing's clamp lets NaN through; it was taken as 0
    {
      vtkErrorMacro("Cannot read '" << path << "': SliceSpacing must be a number of mm (0: automatic), not NaN.");
      return false;
    }
    const std::string folder = isFolder && !dicomdir ? path : vtksys::SystemTools::GetFilenamePath(path);
    std::vector<lkvtk::DICOMSeriesInfo> series;
    std::string error, note;
    // A folder is searched with its sub-folders (a CD's layout); a file's
    // series lies in the file's own folder.
    const bool found = lkvtk::findDICOMSeries(
      folder.empty() ? "." : folder, series, error, this, isFolder ? lkvtk::kDICOMScanDepth : 1, &note);
    if (!note.empty())
      vtkWarningMacro("'" << (folder.empty() ? std::string(".") : folder) << "': " << note << ".");
    if (!found)
    {
      // A folder that holds a volume file (a NIfTI beside its licence) is a
      // likely slip: name the files the user may have meant.
      std::string hint;
      if (isFolder)
      {
        vtkNew<vtkDirectory> listing;
        std::vector<std::string> volumes;
        if (listing->Open(path.c_str()))
        {
          for (vtkIdType f = 0; f < listing->GetNumberOfFiles(); ++f)
          {
            const std::string file = listing->GetFile(f);
            if (isVolumeFileName(lower(file)))
              volumes.push_back(file);
          }
        }
        std::sort(volumes.begin(), volumes.end());
        const std::string sep = (!path.empty() && (path.back() == '/' || path.back() == '\\')) ? "" : "/";
        for (std::size_t v = 0; v < volumes.size() && v < 3; ++v)
        {
          hint += (v == 0 ? "'" : ", '") + path + sep + volumes[v] + "'";
        }
        if (volumes.size() > 3)
        {
          hint += " and " + std::to_string(volumes.size() - 3) + " more";
        }
        if (!hint.empty())
        {
          hint = volumes.size() == 1 ? ". It holds the volume file " + hint + ": give that file instead"
                                     : ". It holds the volume files " + hint + ": give one of them instead";
        }
      }
      vtkErrorMacro("Cannot read '" << path << "': " << error << hint
                                    << ". Supported inputs: a DICOM folder or file, .nrrd, .nhdr, .mha, .mhd, .nii, .nii.gz.");
      return false;
    }
    this->NumberOfSeries = static_cast<int>(series.size());
    int chosen = 0;
    if (!isFolder)
    {
      chosen = lkvtk::seriesHoldingFile(series, path);
      if (chosen < 0)
      {
        vtkErrorMacro("Cannot read '" << path << "': it is not a DICOM image file.");
        return false;
      }
    }
    else if (this->SeriesIndex >= 0)
    {
      if (this->SeriesIndex >= this->NumberOfSeries)
      {
        vtkErrorMacro("SeriesIndex " << this->SeriesIndex << " is out of range: the folder has "
                                     << this->NumberOfSeries << " series.");
        return false;
      }
      chosen = this->SeriesIndex;
    }
    else if (series.size() > 1)
    {
      // Each series with the folder it lies in, when they lie apart (a CD's
      // series folders), so the user can tell the bone kernel's from the scout's.
      std::vector<std::string> where;
      for (const auto& one : series)
      {
        const std::string dirOf = vtksys::SystemTools::GetFilenamePath(one.files.front());
        where.push_back(vtksys::SystemTools::RelativePath(vtksys::SystemTools::CollapseFullPath(folder),
          vtksys::SystemTools::CollapseFullPath(dirOf)));
      }
      const bool apart = std::any_of(where.begin(), where.end(), [&](const std::string& w) { return w != where[0]; });
      std::ostringstream os;
      for (std::size_t s = 0; s < series.size(); ++s)
      {
        os << "\n  [" << s << "] " << series[s].files.size() << " images, " << series[s].modality
           << " '" << series[s].description << "' " << series[s].uid;
        if (apart)
          os << " in '" << (where[s].empty() ? std::string(".") : where[s]) << "'";
      }
      vtkWarningMacro("The folder holds " << series.size()
                                          << " series; reading the largest, [0] (SeriesIndex selects another):"
                                          << os.str());
    }
    vtkNew<vtkImageData> volume;
    if (series[static_cast<std::size_t>(chosen)].sopClass == lkvtk::kSegmentationStorage)
    {
      // A DICOM SEG: its segments, by number and name, in layers as 3D
      // Slicer's are (the bone surface filter takes one).
      this->FileFormat = "DICOM SEG";
      if (!lkvtk::readDICOMSegmentation(
            series[static_cast<std::size_t>(chosen)], volume, this->PatientMatrix, segments, error, this))
      {
        vtkErrorMacro("Cannot read '" << path << "': " << error << ".");
        return false;
      }
      reference = lkvtk::referencedImageFile(series[static_cast<std::size_t>(chosen)].files.front(), series);
      this->OrientationKnown = true;
      image = volume;
      image->GetSpacing(spacing);
    }
    else
    {
      lkvtk::DICOMGeometryReport report;
      if (!lkvtk::readDICOMSeries(series[static_cast<std::size_t>(chosen)], this->SliceSpacing, volume,
            this->PatientMatrix, report, error, this))
      {
        vtkErrorMacro("Cannot read '" << path << "': " << error << ".");
        return false;
      }
      if (!report.wideGaps.empty())
        vtkWarningMacro(<< wideGapsWarning(report));
      if (report.interceptWithoutSlope)
        vtkWarningMacro("The CT's images carry a RescaleIntercept but no RescaleSlope (DICOM requires both): "
                        "the intercept was applied with a slope of 1.");
      if (report.ctWithoutRescale && report.lowestValue > -500.0)
        vtkWarningMacro("The CT's images carry no RescaleIntercept, so their stored values are taken as "
                        "Hounsfield units; but the lowest is "
          << static_cast<long long>(report.lowestValue)
          << ", where air would be near -1000: the values look shifted (a cone-beam scanner's export often is), "
             "and an iso value in HU misses the bone. Choose it from the values themselves (--iso).");
      // A CT exported with the structure set drawn on it: its ROIs are a
      // file away, in its folder or, when a study is exported one series to
      // a folder, in a folder beside the CT's.
      const std::string& uid = series[static_cast<std::size_t>(chosen)].uid;
      auto sets =
        lkvtk::findDICOMStructureSets(folder.empty() ? "." : folder, isFolder ? lkvtk::kDICOMScanDepth : 1);
      std::size_t beside = 0;
      if (std::none_of(sets.begin(), sets.end(), [&](const auto& set) { return set.drawnOn(uid); }))
      {
        // Beside the CT's own folder (a sub-folder of the one read, on a
        // CD); only those drawn on this series: the study's other sets are
        // not this CT's.
        const std::string& ctFile = series[static_cast<std::size_t>(chosen)].files.front();
        const std::string ctFolder = vtksys::SystemTools::GetFilenamePath(ctFile);
        for (const auto& set : lkvtk::findDICOMStructureSetsBeside(ctFolder.empty() ? "." : ctFolder, ctFile))
          if (set.drawnOn(uid) &&
            std::none_of(sets.begin(), sets.end(), [&](const auto& known) { return known.file == set.file; }))
          {
            sets.push_back(set);
            ++beside;
          }
      }
      if (!sets.empty())
        vtkWarningMacro(<< structureSetsNote(sets, uid, beside));
      for (const auto& set : sets)
        if (set.drawnOn(uid))
        {
          structureSets.push_back(set.file);
          structureSetROIs.push_back(set.roiNames);
        }
      this->GantryTilt = report.gantryTiltDegrees;
      this->MinimumSliceGap = report.minGap;
      this->MaximumSliceGap = report.maxGap;
      this->NumberOfInputSlices = report.inputSlices;
      reference = series[static_cast<std::size_t>(chosen)].files.front();
      this->OrientationKnown = true; // every slice's ImagePositionPatient and ImageOrientationPatient
      image = volume;
      image->GetSpacing(spacing);
    }
  }

  // A segmentation whose segments overlap comes in layers, one component each
  // (the bone surface filter takes one segment of one layer).
  const int components = image->GetNumberOfScalarComponents();
  const auto outsideTheLayers =
    std::find_if(segments.begin(), segments.end(), [&](const Segment& seg) { return seg.layer >= components; });
  if (outsideTheLayers != segments.end())
  {
    vtkErrorMacro("'" << path << "' is a segmentation whose segment '" << outsideTheLayers->name << "' is in layer "
                      << outsideTheLayers->layer << ", but it has " << components << " layer"
                      << (components == 1 ? "" : "s") << " (0 to " << components - 1 << ").");
    return false;
  }
  if (components != 1 && segments.empty())
  {
    vtkErrorMacro("'" << path << "' has " << components
                      << " components per voxel; a single-component volume is needed.");
    return false;
  }
  this->Volume->ShallowCopy(image);
  this->Volume->SetOrigin(0.0, 0.0, 0.0);
  this->Volume->SetSpacing(spacing);
  vtkNew<vtkDoubleArray> matrix;
  matrix->SetName("PatientMatrix");
  matrix->SetNumberOfValues(16);
  for (int i = 0; i < 16; ++i)
  {
    matrix->SetValue(i, this->PatientMatrix->GetElement(i / 4, i % 4));
  }
  this->Volume->GetFieldData()->AddArray(matrix);
  if (!segments.empty())
  {
    vtkNew<vtkStringArray> names;
    names->SetName("SegmentNames");
    vtkNew<vtkIntArray> values;
    values->SetName("SegmentLabelValues");
    vtkNew<vtkIntArray> layers;
    layers->SetName("SegmentLayers");
    for (const Segment& seg : segments)
    {
      names->InsertNextValue(seg.name);
      values->InsertNextValue(seg.label);
      layers->InsertNextValue(seg.layer);
    }
    this->Volume->GetFieldData()->AddArray(names);
    this->Volume->GetFieldData()->AddArray(values);
    this->Volume->GetFieldData()->AddArray(layers);
  }
  if (this->OrientationKnown)
  {
    // 3D Slicer's name for a data set's coordinate system (as its model files
    // carry it); vtkLKBoneSurfaceFilter passes it on to the surface.
    vtkNew<vtkStringArray> space;
    space->SetName("SPACE");
    space->InsertNextValue("LPS");
    this->Volume->GetFieldData()->AddArray(space);
  }
  this->ReferenceImageFileName = reference;
  this->StructureSetFiles = structureSets;
  this->StructureSetROINames = structureSetROIs;
  this->VolumeTime = this->GetMTime();
  return true;
}

const char* vtkLKMedicalImageReader::GetStructureSetFileName(int i) const
{
  return i >= 0 && i < this->GetNumberOfStructureSets() ? this->StructureSetFiles[static_cast<std::size_t>(i)].c_str()
                                                        : nullptr;
}

int vtkLKMedicalImageReader::GetNumberOfStructureSetROIs(int i) const
{
  return i >= 0 && i < this->GetNumberOfStructureSets()
    ? static_cast<int>(this->StructureSetROINames[static_cast<std::size_t>(i)].size())
    : 0;
}

const char* vtkLKMedicalImageReader::GetStructureSetROIName(int i, int roi) const
{
  if (roi < 0 || roi >= this->GetNumberOfStructureSetROIs(i))
    return nullptr;
  return this->StructureSetROINames[static_cast<std::size_t>(i)][static_cast<std::size_t>(roi)].c_str();
}

// The segments are read from the volume's field data, which the reader
// writes once per read (and a stopped or failed read clears).
int vtkLKMedicalImageReader::GetNumberOfSegments() const
{
  auto* names = vtkStringArray::SafeDownCast(this->Volume->GetFieldData()->GetAbstractArray("SegmentNames"));
  return names ? static_cast<int>(names->GetNumberOfValues()) : 0;
}

const char* vtkLKMedicalImageReader::GetSegmentName(int i) const
{
  if (i < 0 || i >= this->GetNumberOfSegments())
    return nullptr;
  return vtkStringArray::SafeDownCast(this->Volume->GetFieldData()->GetAbstractArray("SegmentNames"))
    ->GetValue(i)
    .c_str();
}

int vtkLKMedicalImageReader::GetSegmentLabelValue(int i) const
{
  vtkDataArray* values = this->Volume->GetFieldData()->GetArray("SegmentLabelValues");
  return i >= 0 && i < this->GetNumberOfSegments() && values ? static_cast<int>(values->GetTuple1(i)) : 0;
}

int vtkLKMedicalImageReader::GetSegmentLayer(int i) const
{
  vtkDataArray* layers = this->Volume->GetFieldData()->GetArray("SegmentLayers");
  return i >= 0 && i < this->GetNumberOfSegments() && layers ? static_cast<int>(layers->GetTuple1(i)) : -1;
}

int vtkLKMedicalImageReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  if (this->VolumeTime == 0 || this->VolumeTime != this->GetMTime() ||
    this->Volume->GetNumberOfPoints() == 0)
  {
    this->ReadStopped = false;
    // As the executive does before RequestData: a stop asked during an
    // earlier read (which ended without a data request) is not this read's.
    this->SetAbortExecute(0);
    const bool read = this->ReadVolume();
    if (read && this->GetAbortExecute())
    {
      // Stopped while reading (the inner reader answers the stop too): the
      // volume holds part of the voxels. An empty output, as every latticekit
      // filter gives when stopped, not a volume half read. The executive
      // clears AbortExecute before RequestData, so the stop is kept here.
      this->Volume->Initialize(); // its segments' field data too
      this->VolumeTime = 0;
      this->ReadStopped = true;
      vtkWarningMacro("Aborted.");
      const int none[6] = { 0, -1, 0, -1, 0, -1 };
      outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), none, 6);
      return 1;
    }
    if (!read)
    {
      this->VolumeTime = 0;
      // The executive skips RequestData after a failed request: clear the
      // output here, or it would keep the volume of an earlier read.
      if (vtkImageData* output = vtkImageData::GetData(outputVector))
      {
        output->Initialize();
      }
      return 0;
    }
  }
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), this->Volume->GetExtent(), 6);
  outInfo->Set(vtkDataObject::SPACING(), this->Volume->GetSpacing(), 3);
  outInfo->Set(vtkDataObject::ORIGIN(), this->Volume->GetOrigin(), 3);
  vtkDataObject::SetPointDataActiveScalarInfo(
    outInfo, this->Volume->GetScalarType(), this->Volume->GetNumberOfScalarComponents());
  return 1;
}

int vtkLKMedicalImageReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkImageData* output = vtkImageData::GetData(outputVector);
  if (this->Volume->GetNumberOfPoints() == 0)
  {
    output->Initialize();
    return this->ReadStopped ? 1 : 0;
  }
  output->ShallowCopy(this->Volume);
  return 1;
}
