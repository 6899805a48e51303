#include "AppSupport.h"
#include "AtomicFile.h"
#include "MeshFileCheck.h"
#include "vtkLKMedicalImageReader.h"
#include "vtkLKText.h"

#include <vtkPlane.h>
#include <vtkPlaneCollection.h>
#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkErrorCode.h>
#include <vtkFieldData.h>
#include <vtkGLTFWriter.h>
#include <vtkLogger.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkOBJReader.h>
#include <vtkOBJWriter.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkPLYReader.h>
#include <vtkPLYWriter.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkPolyDataWriter.h>
#include <vtkRenderWindow.h>
#include <vtkSTLReader.h>
#include <vtkSTLWriter.h>
#include <vtkStringArray.h>
#include <vtkTriangleFilter.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>
#include <vtkWriter.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtksys/Directory.hxx>
#include <vtksys/SystemTools.hxx>

#include <X11/Xlib.h>

#include <execinfo.h>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstring>

#include <algorithm>
#include <cmath>
#include <regex>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

namespace lkapp
{

namespace
{
const char* g_tool = "latticekit";

/// The crash note (setCrashNote): written into the buffer not in use, then
/// made current by one store, so that a crash while it changes prints the
/// whole old note or the whole new one.
char g_notes[2][4096];
std::size_t g_noteLengths[2] = { 0, 0 };
volatile std::sig_atomic_t g_note = -1;

/// Only async-signal-safe calls: write(2), backtrace_symbols_fd (preloaded in
/// installCrashReport), raise once the default action is back.
void reportCrash(int signal)
{
  const char* name = signal == SIGSEGV ? "SIGSEGV, a bad memory access"
    : signal == SIGBUS               ? "SIGBUS"
    : signal == SIGFPE               ? "SIGFPE"
    : signal == SIGILL               ? "SIGILL"
                                     : "SIGABRT";
  char number[8];
  int n = 0;
  for (int v = signal; v > 0 && n < 7; v /= 10)
    number[n++] = static_cast<char>('0' + v % 10);
  char line[256];
  std::size_t at = 0;
  auto add = [&](const char* text) {
    for (; *text && at + 1 < sizeof(line); ++text)
      line[at++] = *text;
  };
  add("\n");
  add(g_tool);
  add(": crashed (signal ");
  while (n > 0 && at + 1 < sizeof(line))
    line[at++] = number[--n];
  add(", ");
  add(name);
  add("); the call stack:\n");
  ssize_t ignored = write(STDERR_FILENO, line, at);
  (void)ignored;
  void* frames[64];
  const int count = backtrace(frames, 64);
  backtrace_symbols_fd(frames, count, STDERR_FILENO);
  if (const int note = g_note; note >= 0)
  {
    ignored = write(STDERR_FILENO, g_notes[note], g_noteLengths[note]);
    (void)ignored;
  }
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

std::vector<std::string> g_errors, g_warnings;
bool g_quiet = false;

std::string joined(const std::vector<std::string>& messages, int from)
{
  std::string all;
  for (std::size_t i = static_cast<std::size_t>(std::max(from, 0)); i < messages.size(); ++i)
    all += (all.empty() ? "" : "\n") + messages[i];
  return all;
}

std::string lower(std::string s)
{
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return std::tolower(c); });
  return s;
}

} // namespace

std::string updateKeepingErrors(vtkAlgorithm* algorithm)
{
  // An observer of ErrorEvent takes the error: VTK then does not print it.
  std::string last;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetClientData(&last);
  onError->SetCallback([](vtkObject*, unsigned long, void* cd, void* call) {
    *static_cast<std::string*>(cd) = call ? cleanMessage(static_cast<const char*>(call)) : std::string();
  });
  const unsigned long tag = algorithm->AddObserver(vtkCommand::ErrorEvent, onError);
  algorithm->Update();
  algorithm->RemoveObserver(tag);
  return last;
}

std::string cleanMessage(const std::string& text)
{
  std::string m = text;
  const auto nl = m.find('\n');
  if (m.rfind("ERROR: In", 0) == 0 || m.rfind("Warning: In", 0) == 0 ||
    m.rfind("Generic Warning: In", 0) == 0)
  {
    m = nl == std::string::npos ? m : m.substr(nl + 1);
  }
  const auto paren = m.find("): ");
  if (paren != std::string::npos && paren < 80)
  {
    m = m.substr(paren + 3);
  }
  while (!m.empty() && (m.back() == '\n' || m.back() == ' '))
  {
    m.pop_back();
  }
  return m;
}

namespace
{

class AppOutputWindow : public vtkOutputWindow
{
public:
  static AppOutputWindow* New();
  vtkTypeMacro(AppOutputWindow, vtkOutputWindow);
  void DisplayErrorText(const char* text) override
  {
    const std::string m = cleanMessage(text);
    if (m.find("returned failure for request") != std::string::npos)
    {
      return; // the executive repeating the filter's own error
    }
    g_errors.push_back(m);
    std::cerr << "\nerror: " << m << std::endl;
  }
  void DisplayWarningText(const char* text) override
  {
    // Also with --quiet, which silences the progress bar only: a warning
    // says something about the result (a lattice above its target vertex
    // count, a volume without orientation) that a script must not lose.
    const std::string m = cleanMessage(text);
    g_warnings.push_back(m);
    std::cerr << "\nwarning: " << m << std::endl;
  }
  void DisplayGenericWarningText(const char* text) override { this->DisplayWarningText(text); }
  void DisplayDebugText(const char*) override {}
  void DisplayText(const char* text) override
  {
    if (!g_quiet)
    {
      std::cerr << text;
    }
  }
};
vtkStandardNewMacro(AppOutputWindow);
} // namespace

void installCrashReport(const char* tool)
{
  g_tool = tool;
  std::setvbuf(stdout, nullptr, _IOLBF, BUFSIZ);
  void* frame[1];
  backtrace(frame, 1); // loads libgcc now: the handler must not
  struct sigaction action;
  std::memset(&action, 0, sizeof(action));
  action.sa_handler = reportCrash;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESETHAND | SA_NODEFER;
  for (int signal : { SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT })
    sigaction(signal, &action, nullptr);
  // A write past the file size limit (ulimit -f) then fails with EFBIG and
  // is reported like a full disk, instead of killing the tool mid-file.
  std::signal(SIGXFSZ, SIG_IGN);
}

void setCrashNote(const std::string& note)
{
  if (note.empty())
  {
    g_note = -1;
    return;
  }
  const int next = g_note == 0 ? 1 : 0;
  std::string text = g_tool + std::string(": ") + note;
  text.resize(std::min<std::size_t>(text.size(), sizeof(g_notes[next]) - 1));
  text += '\n';
  std::memcpy(g_notes[next], text.data(), text.size());
  g_noteLengths[next] = text.size();
  g_note = next;
}

void installMessageHandler(bool quiet)
{
  g_quiet = quiet;
  // VTK's logger would print every message a second time, in its own format.
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  vtkNew<AppOutputWindow> window;
  vtkOutputWindow::SetInstance(window);
}

int errorCount()
{
  return static_cast<int>(g_errors.size());
}

std::string errors()
{
  return joined(g_errors, 0);
}

std::string errorsSince(int count)
{
  return joined(g_errors, count);
}

void clearErrors()
{
  g_errors.clear();
}

int warningCount()
{
  return static_cast<int>(g_warnings.size());
}

std::string warningsSince(int count)
{
  return joined(g_warnings, count);
}

ProgressBar::ProgressBar(vtkAlgorithm* algorithm, const std::string& label, bool enabled)
  : label_(label)
  , enabled_(enabled)
  , errorsAtStart_(errorCount())
  , algorithm_(algorithm)
{
  if (!enabled_ || !algorithm_)
  {
    return;
  }
  vtkNew<vtkCallbackCommand> cb;
  cb->SetClientData(this);
  cb->SetCallback([](vtkObject*, unsigned long, void* cd, void* call) {
    static_cast<ProgressBar*>(cd)->update(*static_cast<double*>(call));
  });
  tag_ = algorithm_->AddObserver(vtkCommand::ProgressEvent, cb);
  update(0.0);
}

ProgressBar::~ProgressBar()
{
  finish();
  if (algorithm_ && tag_)
  {
    algorithm_->RemoveObserver(tag_);
  }
}

void ProgressBar::update(double fraction)
{
  if (!enabled_ || finished_)
  {
    return;
  }
  if (errorCount() > errorsAtStart_)
  {
    finished_ = true; // the error message has ended the bar's line
    return;
  }
  const int percent = static_cast<int>(std::lround(100.0 * std::clamp(fraction, 0.0, 1.0)));
  if (!isatty(2))
  {
    // A log, not a terminal: one line, a mark every 10 %.
    const int step = percent / 10 * 10;
    if (step > lastDrawn_)
    {
      std::cerr << (lastDrawn_ < 0 ? label_ + " " : std::string(" ")) << step << "%" << std::flush;
      lastDrawn_ = step;
    }
    return;
  }
  if (percent <= lastDrawn_)
  {
    return; // never backwards: a reader's executive resets its progress to 0 after the read
  }
  lastDrawn_ = percent;
  const int width = 30;
  const int filled = percent * width / 100;
  std::cerr << "\r" << label_ << " [" << std::string(static_cast<std::size_t>(filled), '#')
            << std::string(static_cast<std::size_t>(width - filled), '.') << "] " << percent << "%"
            << std::flush;
}

void ProgressBar::finish()
{
  if (enabled_ && !finished_ && errorCount() == errorsAtStart_)
  {
    update(1.0);
    std::cerr << std::endl;
  }
  finished_ = true;
}

namespace
{
/// "LPS" or "RAS" where a header or comment holds 3D Slicer's tag
/// ("SPACE=LPS"), else "".
std::string spaceTagIn(const char* text)
{
  const std::string t = text ? text : "";
  for (const char* space : { "LPS", "RAS" })
    if (t.find(std::string("SPACE=") + space) != std::string::npos)
      return space;
  return {};
}

/// The leading comment lines of an OBJ file, where 3D Slicer puts its tag.
std::string objComments(const std::string& path)
{
  std::ifstream in(path);
  std::string line, comments;
  while (std::getline(in, line) && !line.empty() && line[0] == '#' && comments.size() < 4096)
    comments += line + "\n";
  return comments;
}

} // namespace

std::string coordinateSpace(vtkPolyData* mesh)
{
  auto* tag = mesh && mesh->GetFieldData()
    ? vtkStringArray::SafeDownCast(mesh->GetFieldData()->GetAbstractArray("SPACE"))
    : nullptr;
  if (!tag || tag->GetNumberOfValues() < 1)
    return {};
  const std::string value = tag->GetValue(0);
  return value == "LPS" || value == "RAS" ? value : std::string();
}

void setCoordinateSpace(vtkPolyData* mesh, const std::string& space)
{
  vtkNew<vtkFieldData> fields; // a copy: the mesh may share its field data with a filter's output
  fields->DeepCopy(mesh->GetFieldData());
  fields->RemoveArray("SPACE");
  if (!space.empty())
  {
    vtkNew<vtkStringArray> tag;
    tag->SetName("SPACE");
    tag->InsertNextValue(space);
    fields->AddArray(tag);
  }
  mesh->SetFieldData(fields);
}

std::string specialFileKind(const std::string& path)
{
  struct stat info;
  if (stat(path.c_str(), &info) != 0 || S_ISREG(info.st_mode) || S_ISDIR(info.st_mode))
    return {};
  return S_ISFIFO(info.st_mode) ? "pipe" : "device"; // a socket is a device here
}

vtkSmartPointer<vtkPolyData> readMesh(const std::string& path, std::string& error)
{
  if (vtksys::SystemTools::FileIsDirectory(path))
  {
    error = "cannot read '" + path + "': it is a folder, not a mesh file";
    return nullptr;
  }
  if (!vtksys::SystemTools::FileExists(path, true))
  {
    error = "cannot open '" + path + "': no such file";
    return nullptr;
  }
  // VTK's readers seek in their files.
  if (const std::string kind = specialFileKind(path); !kind.empty())
  {
    error = "cannot read '" + path + "': it is not a file but a " + kind + "; the mesh must be a file to be read";
    return nullptr;
  }
  const std::string ext = lower(vtksys::SystemTools::GetFilenameLastExtension(path));
  // What VTK's readers do not check themselves (MeshFileCheck.h): vtkPLYReader
  // crashes on a truncated file, vtkSTLReader reads part of one silently.
  const std::string problem = ext == ".ply" ? plyFileProblem(path) : ext == ".stl" ? stlFileProblem(path) : "";
  if (!problem.empty())
  {
    error = "cannot read '" + path + "': the file is corrupt (" + problem + ")";
    return nullptr;
  }
  vtkSmartPointer<vtkAlgorithm> reader;
  if (ext == ".vtp")
  {
    auto r = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else if (ext == ".vtk")
  {
    auto r = vtkSmartPointer<vtkPolyDataReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else if (ext == ".stl")
  {
    auto r = vtkSmartPointer<vtkSTLReader>::New();
    r->SetFileName(path.c_str());
    r->MergingOn();
    reader = r;
  }
  else if (ext == ".ply")
  {
    auto r = vtkSmartPointer<vtkPLYReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else if (ext == ".obj")
  {
    auto r = vtkSmartPointer<vtkOBJReader>::New();
    r->SetFileName(path.c_str());
    reader = r;
  }
  else
  {
    error = "cannot read '" + path + "': unknown extension (use " + meshExtensions() + ")";
    return nullptr;
  }
  const int before = errorCount();
  // The legacy reader only warns of data shorter than its header declares
  // ("Error reading binary data!", from a function without an object, so
  // after it has been printed) and goes on with part of the mesh: such a
  // warning is an error here.
  const int warningsBefore = warningCount();
  try
  {
    reader->Update();
  }
  catch (const std::exception& e)
  {
    // vtkPLYReader sizes its arrays from the header: a corrupt count throws.
    error = "cannot read '" + path + "': the file is corrupt (" + e.what() + ")";
    return nullptr;
  }
  for (int w = warningsBefore; ext == ".vtk" && w < warningCount(); ++w)
  {
    const std::string& warning = g_warnings[static_cast<std::size_t>(w)];
    if (warning.rfind("Error reading", 0) == 0)
    {
      error = "cannot read '" + path + "': the file is corrupt: its data ends before its header says (VTK: " + warning + ")";
      return nullptr;
    }
  }
  auto* pd = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  if (errorCount() != before || !pd || pd->GetNumberOfPoints() == 0)
  {
    error = "cannot read '" + path + "': the file is empty or corrupt";
    return nullptr;
  }
  auto result = vtkSmartPointer<vtkPolyData>::New();
  result->ShallowCopy(pd);
  // The coordinate system the file names (3D Slicer's tag), kept as the
  // field data "SPACE" that .vtp files carry it in, so that what a tool
  // writes from this mesh names it too.
  std::string space;
  if (auto* r = vtkPolyDataReader::SafeDownCast(reader))
    space = spaceTagIn(r->GetHeader());
  else if (auto* r = vtkSTLReader::SafeDownCast(reader))
    space = spaceTagIn(r->GetHeader());
  else if (auto* r = vtkPLYReader::SafeDownCast(reader))
    for (vtkIdType i = 0; r->GetComments() && i < r->GetComments()->GetNumberOfValues() && space.empty(); ++i)
      space = spaceTagIn(r->GetComments()->GetValue(i).c_str());
  else if (vtkOBJReader::SafeDownCast(reader))
    space = spaceTagIn(objComments(path).c_str());
  else
    space = coordinateSpace(result);
  setCoordinateSpace(result, space);
  return result;
}

std::string pieceFileStem(std::size_t p, const std::string& name)
{
  std::string stem = "piece" + std::to_string(p);
  std::vector<char32_t> characters;
  lkvtk::decodeUTF8(name, &characters); // a valid piece name is UTF-8
  // Kept: ASCII letters and digits, '-', '.', and letters beyond ASCII;
  // not the invisible ones (no-break and zero-width spaces, a soft hyphen,
  // the marks that turn text right to left, which could make a name read
  // as another extension).
  auto kept = [](char32_t c) {
    if (c < 0x80)
      return std::isalnum(static_cast<int>(c)) != 0 || c == '-' || c == '.';
    return !lkvtk::isControl(c) && c != 0xA0 && c != 0xAD && !(c >= 0x2000 && c <= 0x200F) &&
      !(c >= 0x2028 && c <= 0x202F) && !(c >= 0x205F && c <= 0x206F) && c != 0x3000 && c != 0xFEFF;
  };
  std::string suffix;
  for (const char32_t c : characters)
    if (kept(c))
      suffix += lkvtk::encodeUTF8(c);
    else if (!suffix.empty() && suffix.back() != '_')
      suffix += '_';
  while (!suffix.empty() && suffix.back() == '_')
    suffix.pop_back();
  return suffix.empty() ? stem : stem + "-" + suffix;
}

bool isPieceFileName(const std::string& name)
{
  const std::string stem = vtksys::SystemTools::GetFilenameWithoutLastExtension(name);
  const std::string ext = lower(vtksys::SystemTools::GetFilenameLastExtension(name));
  if (std::none_of(pieceExtensions.begin(), pieceExtensions.end(), [&](const char* e) { return ext == e; }) ||
    stem.size() < 6 || stem.rfind("piece", 0) != 0)
    return false;
  const std::size_t end = stem.find_first_not_of("0123456789", 5);
  return end > 5 && (end == std::string::npos || stem[end] == '-');
}

bool isLatticeFileName(const std::string& name)
{
  static const std::string prefix = "lattice_";
  return name.rfind(prefix, 0) == 0 && lower(vtksys::SystemTools::GetFilenameLastExtension(name)) == ".vtp" &&
    isPieceFileName(name.substr(prefix.size()));
}

std::array<double, 3> guideDirection(const double approach[3])
{
  std::array<double, 3> along{};
  for (int c = 0; c < 3; ++c)
    along[c] = std::abs(approach[c]) < 5e-4 ? 0.0 : -approach[c];
  return along;
}

vtkSmartPointer<vtkPlaneCollection> planeCollection(const std::vector<std::array<double, 6>>& planes)
{
  auto collection = vtkSmartPointer<vtkPlaneCollection>::New();
  for (const auto& plane : planes)
  {
    vtkNew<vtkPlane> p;
    p->SetOrigin(plane.data());
    p->SetNormal(plane.data() + 3);
    collection->AddItem(p);
  }
  return collection;
}

bool isGuideFileName(const std::string& name)
{
  static const std::regex guide("guide_(stroke[0-9]+|strokes[0-9]+(-[0-9]+)+)[.](stl|vtp)");
  return std::regex_match(name, guide);
}

bool isInFolder(const std::string& path, const std::string& folder)
{
  return !path.empty() && !folder.empty() &&
    vtksys::SystemTools::GetFilenamePath(vtksys::SystemTools::CollapseFullPath(path)) ==
    vtksys::SystemTools::CollapseFullPath(folder);
}

bool isExportedFile(const std::string& path, const std::string& folder, std::initializer_list<const char*> others)
{
  if (!isInFolder(path, folder))
    return false;
  const std::string name = vtksys::SystemTools::GetFilenameName(vtksys::SystemTools::CollapseFullPath(path));
  return isPieceFileName(name) || std::any_of(others.begin(), others.end(), [&](const char* o) { return name == o; });
}

std::vector<std::string> filesNotWritten(
  const std::string& folder, bool (*isKind)(const std::string&), const std::vector<std::string>& written)
{
  std::vector<std::string> left;
  vtksys::Directory listing;
  if (listing.Load(folder))
    for (unsigned long i = 0; i < listing.GetNumberOfFiles(); ++i)
    {
      const std::string name = listing.GetFile(i);
      if (isKind(name) && std::find(written.begin(), written.end(), name) == written.end())
        left.push_back(name);
    }
  return left;
}

bool removeStaleExports(const std::string& folder, const std::vector<std::string>& pieceStems,
  const std::vector<std::string>& others, std::string& error)
{
  std::vector<std::string> stale;
  vtksys::Directory listing;
  if (listing.Load(folder))
    for (unsigned long i = 0; i < listing.GetNumberOfFiles(); ++i)
    {
      const std::string name = listing.GetFile(i);
      const std::string stem = vtksys::SystemTools::GetFilenameWithoutLastExtension(name);
      if (isPieceFileName(name) && std::find(pieceStems.begin(), pieceStems.end(), stem) == pieceStems.end())
        stale.push_back(folder + "/" + name);
    }
  std::sort(stale.begin(), stale.end());
  for (const std::string& name : others)
    stale.push_back(folder + "/" + name);
  for (const std::string& path : stale)
    if (vtksys::SystemTools::FileExists(path, true) && !vtksys::SystemTools::RemoveFile(path))
    {
      error = "cannot remove '" + path + "', which an earlier export left and this one does not make";
      return false;
    }
  return true;
}

namespace
{
/// Whether `text`, vtkOBJWriter's file of `mesh`, is whole: VTK 9.1's writer
/// ends its lines with a newline and writes a "v" line per point and an "f"
/// line per polygon and per triangle of a strip, then an "l" line per line
/// cell (vertex cells are not written). A write cut short has fewer.
bool objIsComplete(const std::string& text, vtkPolyData* mesh)
{
  if (text.empty() || text.back() != '\n')
    return false;
  vtkIdType points = 0, faces = 0;
  for (std::size_t at = 0; at < text.size();)
  {
    if (text.compare(at, 2, "v ") == 0)
      ++points;
    else if (text.compare(at, 2, "f ") == 0 || text.compare(at, 2, "l ") == 0)
      ++faces;
    const std::size_t next = text.find('\n', at);
    at = next == std::string::npos ? text.size() : next + 1;
  }
  vtkIdType expected = mesh->GetNumberOfPolys() + mesh->GetNumberOfLines();
  if (vtkCellArray* strips = mesh->GetStrips())
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    for (strips->InitTraversal(); strips->GetNextCell(n, ids);)
      expected += std::max<vtkIdType>(n - 2, 0);
  }
  return points == mesh->GetNumberOfPoints() && faces == expected;
}
} // namespace

bool writeMesh(vtkPolyData* mesh, const std::string& path, std::string& error, const std::string& spaceGiven)
{
  const std::string ext = lower(vtksys::SystemTools::GetFilenameLastExtension(path));
  // 3D Slicer's tag for the coordinate system, in each format where Slicer
  // writes and reads it: a .vtp's field data "SPACE", "SPACE=LPS" in a .vtk
  // or .stl header, a .ply comment, a leading .obj comment.
  const std::string space = spaceGiven.empty() ? coordinateSpace(mesh) : spaceGiven;
  const std::string header = "latticekit output" + (space.empty() ? std::string() : ". SPACE=" + space);
  vtkSmartPointer<vtkPolyData> tagged = mesh;
  if (coordinateSpace(mesh) != space)
  {
    tagged = vtkSmartPointer<vtkPolyData>::New();
    tagged->ShallowCopy(mesh);
    setCoordinateSpace(tagged, space);
  }
  mesh = tagged;
  // Every file is written whole or not at all (AtomicFile.h): the writers
  // that can write to memory do, and the bytes go to the disk through
  // writeFileAtomically; the others write a temporary file beside `path`.
  const int before = errorCount();
  const std::string writeFailed = "a write failed (no space left on the disk, or past the file size limit)";
  // A writer's own error becomes part of this one (watch() before Update):
  // printed as it came, it would name the temporary file.
  std::string writerMessage;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetClientData(&writerMessage);
  onError->SetCallback([](vtkObject*, unsigned long, void* message, void* text) {
    if (text)
      *static_cast<std::string*>(message) = cleanMessage(static_cast<const char*>(text));
  });
  auto watch = [&](vtkAlgorithm* writer) { writer->AddObserver(vtkCommand::ErrorEvent, onError); };
  auto failed = [&](vtkAlgorithm* writer) {
    const unsigned long code = writer->GetErrorCode();
    if (errorCount() == before && code == 0 && writerMessage.empty())
      return false;
    // Below FirstVTKErrorCode the code is the system's errno.
    const std::string reason = code == vtkErrorCode::OutOfDiskSpaceError ? writeFailed
      : code > 0 && code < vtkErrorCode::FirstVTKErrorCode ? std::string(std::strerror(static_cast<int>(code)))
      : !writerMessage.empty() ? writerMessage
      : code != 0 ? vtkErrorCode::GetStringFromErrorCode(code) : "";
    error = "cannot write '" + path + "'" + (reason.empty() ? std::string() : ": " + reason);
    return true;
  };
  std::string contents;
  if (ext == ".vtp")
  {
    vtkNew<vtkXMLPolyDataWriter> w;
    w->SetInputData(mesh);
    w->SetDataModeToAppended();
    w->SetCompressorTypeToZLib();
    w->WriteToOutputStringOn();
    watch(w);
    w->Update();
    if (failed(w))
      return false;
    contents = w->GetOutputString();
  }
  else if (ext == ".vtk")
  {
    vtkNew<vtkPolyDataWriter> w;
    w->SetInputData(mesh);
    w->SetFileTypeToBinary();
    w->SetHeader(header.c_str());
    w->WriteToOutputStringOn();
    watch(w);
    w->Update();
    if (failed(w))
      return false;
    contents.assign(reinterpret_cast<const char*>(w->GetBinaryOutputString()),
      static_cast<std::size_t>(w->GetOutputStringLength()));
  }
  else if (ext == ".gltf")
  {
    // glTF for the web: one self-contained file; normals go in as NORMAL.
    auto copy = vtkSmartPointer<vtkPolyData>::New();
    copy->ShallowCopy(mesh);
    if (vtkDataArray* normals = copy->GetPointData()->GetNormals())
    {
      auto named = vtkSmartPointer<vtkDataArray>::Take(normals->NewInstance());
      named->DeepCopy(normals);
      named->SetName("NORMAL");
      copy->GetPointData()->AddArray(named);
    }
    // VTK 9.1's writer (made for 3D Tiles) wants buildings: a multiblock of
    // multiblocks of polydata; a flat multiblock crashes it.
    auto building = vtkSmartPointer<vtkMultiBlockDataSet>::New();
    building->SetBlock(0, copy);
    auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
    blocks->SetBlock(0, building);
    vtkNew<vtkGLTFWriter> w;
    w->SetInputData(blocks);
    w->InlineDataOn();
    w->SaveNormalOn();
    watch(w);
    contents = w->WriteToString();
    if (failed(w))
      return false;
  }
  else if (ext == ".stl" || ext == ".ply" || ext == ".obj")
  {
    // Writers without a working memory output (vtkPLYWriter's gives nothing
    // in VTK 9.1) write a temporary file beside `path`, which is checked
    // before it replaces the file: vtkSTLWriter reports a failed write
    // itself; vtkPLYWriter and vtkOBJWriter do not, so the PLY body is
    // checked against its header and the OBJ's lines are counted.
    const std::string temporary = temporaryPathBeside(path);
    vtkSmartPointer<vtkWriter> writer;
    if (ext == ".stl")
    {
      auto w = vtkSmartPointer<vtkSTLWriter>::New();
      auto triangles = vtkSmartPointer<vtkTriangleFilter>::New(); // STL holds triangles only
      triangles->SetInputData(mesh);
      w->SetInputConnection(triangles->GetOutputPort());
      w->SetFileName(temporary.c_str());
      w->SetFileTypeToBinary();
      w->SetHeader(header.c_str());
      writer = w;
    }
    else if (ext == ".ply")
    {
      auto w = vtkSmartPointer<vtkPLYWriter>::New();
      w->SetInputData(mesh);
      w->SetFileName(temporary.c_str());
      w->SetFileTypeToBinary();
      if (!space.empty())
        w->AddComment("SPACE=" + space);
      if (mesh->GetPointData()->GetArray("DistanceColors"))
      {
        w->SetArrayName("DistanceColors");
        w->SetColorModeToDefault();
      }
      writer = w;
    }
    else
    {
      auto w = vtkSmartPointer<vtkOBJWriter>::New();
      w->SetInputData(mesh);
      w->SetFileName(temporary.c_str());
      writer = w;
    }
    watch(writer);
    writer->Update();
    if (failed(writer) || !vtksys::SystemTools::FileExists(temporary, true))
    {
      vtksys::SystemTools::RemoveFile(temporary);
      if (error.empty())
        error = "cannot write '" + path + "'";
      return false;
    }
    if (ext == ".ply" && !plyFileProblem(temporary).empty())
    {
      vtksys::SystemTools::RemoveFile(temporary);
      error = "cannot write '" + path + "': " + writeFailed;
      return false;
    }
    if (ext != ".obj")
      return commitTemporaryFile(temporary, path, error);
    std::ifstream in(temporary, std::ios::binary);
    std::ostringstream body;
    if (!space.empty())
      body << "# " << header << "\n";
    body << in.rdbuf();
    in.close();
    vtksys::SystemTools::RemoveFile(temporary);
    contents = body.str();
    if (!objIsComplete(contents, mesh))
    {
      error = "cannot write '" + path + "': " + writeFailed;
      return false;
    }
  }
  else
  {
    error = "cannot write '" + path + "': unknown extension (use " + meshExtensions() + ")";
    return false;
  }
  return writeFileAtomically(path, contents, error);
}

bool writeScreenshot(vtkRenderWindow* window, const std::string& path, std::string& error)
{
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  vtkNew<vtkPNGWriter> png;
  png->SetInputConnection(grab->GetOutputPort());
  png->WriteToMemoryOn();
  const int before = errorCount();
  png->Write();
  vtkUnsignedCharArray* bytes = png->GetResult();
  if (errorCount() != before || !bytes || bytes->GetNumberOfValues() == 0)
  {
    error = "cannot write '" + path + "': the window's picture could not be read";
    return false;
  }
  return writeFileAtomically(path,
    std::string(reinterpret_cast<const char*>(bytes->GetPointer(0)), static_cast<std::size_t>(bytes->GetNumberOfValues())),
    error);
}

const char* meshExtensions()
{
  return ".vtp, .vtk, .stl, .ply, .obj or .gltf (written only)";
}

namespace
{
/// Decimal text as a person types it: strtod and strtol also skip leading
/// blanks (" 5" was taken, "5 " refused) and read hexadecimal ("0x10" was
/// taken as 16 where a number, not an integer, was asked for).
bool plainNumberText(const std::string& text)
{
  return !text.empty() && !std::isspace(static_cast<unsigned char>(text[0])) &&
    text.find_first_of("xX") == std::string::npos;
}
} // namespace

bool parseDouble(const std::string& text, double& value)
{
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return plainNumberText(text) && end && *end == '\0' && std::isfinite(value);
}

bool parseInt(const std::string& text, long& value)
{
  char* end = nullptr;
  value = std::strtol(text.c_str(), &end, 10);
  return plainNumberText(text) && end && *end == '\0';
}

bool parseNumbers(const std::string& text, double* v, int n)
{
  std::string t = text;
  std::replace(t.begin(), t.end(), ',', ' ');
  std::istringstream is(t);
  std::string word;
  int k = 0;
  while (is >> word)
  {
    if (k == n || !parseDouble(word, v[k]))
    {
      return false;
    }
    ++k;
  }
  return k == n;
}

bool parseTriple(const std::string& text, double v[3])
{
  return parseNumbers(text, v, 3);
}

Arguments::Arguments(int argc, char* argv[], Usage usage)
  : argc_(argc)
  , argv_(argv)
  , usage_(usage)
{
}

bool Arguments::next(std::string& arg)
{
  if (++i_ >= argc_)
  {
    return false;
  }
  arg = argv_[i_];
  if (arg == "-h" || arg == "--help")
  {
    usage_(std::cout);
    std::exit(0);
  }
  return true;
}

std::string Arguments::value(const std::string& arg)
{
  if (i_ + 1 >= argc_)
  {
    std::cerr << "error: " << arg << " needs a value\n";
    std::exit(2);
  }
  const std::string v = argv_[++i_];
  if (!given_.insert(arg).second)
    std::cerr << "warning: " << arg << " is given more than once; the last value, '" << v << "', is taken\n";
  return v;
}

long Arguments::integer(const std::string& arg, long lo, long hi, const char* what)
{
  const std::string v = value(arg);
  long x = 0;
  if (!parseInt(v, x) || x < lo || x > hi)
  {
    std::cerr << "error: " << arg << " needs " << what << ", not '" << v << "'\n";
    std::exit(2);
  }
  return x;
}

void Arguments::labelOrName(const std::string& arg, long& label, std::string& name)
{
  const std::string v = value(arg);
  long x = 0;
  const bool numeric = parseInt(v, x); // a whole number; anything else ("3rd molar") is a name
  if (v.empty() || (numeric && (x < 1 || x > std::numeric_limits<int>::max())))
  {
    std::cerr << "error: " << arg << " needs a label value >= 1 or a segment's name, not '" << v << "'\n";
    std::exit(2);
  }
  label = numeric ? x : 0;
  name = numeric ? std::string() : v;
}

std::string smoothingWords(double imageSmoothing, int iterations)
{
  if (!(imageSmoothing > 0.0) && iterations <= 0)
    return "no smoothing";
  std::ostringstream s;
  if (imageSmoothing > 0.0)
    s << "a Gaussian of " << imageSmoothing << " voxel on the volume" << (iterations > 0 ? ", " : "");
  if (iterations > 0)
    s << iterations << " windowed-sinc iterations on the surface";
  return s.str();
}

std::string unusedIsoNote(double iso, int label, const std::string& input, bool noLabelMapOption)
{
  std::ostringstream note;
  const std::string name = "'" + vtksys::SystemTools::GetFilenameName(input) + "'";
  note << "--iso " << iso << " is not used: ";
  if (label > 0)
    note << "label " << label << " of " << name << " is taken as a 0/1 label map, at 0.5";
  else
    note << name << " is a 0/1 label map, taken at 0.5"
         << (noLabelMapOption ? " (--no-label-map takes it at the --iso value)" : "");
  return note.str();
}

bool readOrganFromStructureSet(
  vtkLKMedicalImageReader* reader, const std::string& name, std::string& note, std::string& error)
{
  note.clear();
  error.clear();
  if (name.empty() || std::strcmp(reader->GetFileFormat(), "DICOM") != 0 || reader->GetNumberOfSegments() > 0)
    return false;
  // The bone surface filter's rule: the exact name, else the name in any case.
  std::vector<int> holding;
  for (bool anyCase : { false, true })
  {
    for (int s = 0; s < reader->GetNumberOfStructureSets(); ++s)
      for (int r = 0; r < reader->GetNumberOfStructureSetROIs(s); ++r)
        if (anyCase ? lower(reader->GetStructureSetROIName(s, r)) == lower(name) : reader->GetStructureSetROIName(s, r) == name)
        {
          holding.push_back(s);
          break;
        }
    if (!holding.empty())
      break;
  }
  if (holding.empty())
    return false;
  if (holding.size() > 1)
  {
    error = "the CT names no segments, and " + std::to_string(holding.size()) +
      " RT structure sets drawn on it have an ROI named '" + name + "': give the file of the one to read:";
    for (int s : holding)
      error += std::string("\n  '") + reader->GetStructureSetFileName(s) + "'";
    return false;
  }
  const std::string file = reader->GetStructureSetFileName(holding.front());
  note = "'" + name + "' is an ROI of the RT structure set '" + file + "', drawn on this CT: read from there";
  reader->SetFileName(file.c_str());
  const int before = errorCount();
  reader->Update();
  if (errorCount() > before)
  {
    error = "cannot read the RT structure set '" + file + "'";
    return false;
  }
  return true;
}

double Arguments::number(const std::string& arg, double lo, double hi, const char* what)
{
  const std::string v = value(arg);
  double x = 0.0;
  if (!parseDouble(v, x) || x < lo || x > hi)
  {
    std::cerr << "error: " << arg << " needs " << what << ", not '" << v << "'\n";
    std::exit(2);
  }
  return x;
}

void Arguments::triple(const std::string& arg, double v[3])
{
  const std::string text = value(arg);
  if (!parseTriple(text, v))
  {
    std::cerr << "error: " << arg << " needs three numbers X,Y,Z, not '" << text << "'\n";
    std::exit(2);
  }
}

void Arguments::box(const std::string& arg, double v[6])
{
  const std::string text = value(arg);
  if (!parseNumbers(text, v, 6))
  {
    std::cerr << "error: " << arg << " needs six numbers XMIN,XMAX,YMIN,YMAX,ZMIN,ZMAX, not '" << text << "'\n";
    std::exit(2);
  }
  if (!isOrderedBox(v))
  {
    std::cerr << "error: " << arg << " needs each min below its max, not '" << text << "'\n";
    std::exit(2);
  }
}

void Arguments::unknown(const std::string& arg)
{
  std::cerr << "error: unknown option " << arg << "\n";
  usage_(std::cerr);
  std::exit(2);
}

bool checkWritable(const std::string& path, std::string& error, bool structureSet)
{
  const std::string ext = lower(vtksys::SystemTools::GetFilenameLastExtension(path));
  if (ext != ".vtp" && ext != ".vtk" && ext != ".stl" && ext != ".ply" && ext != ".obj" && ext != ".gltf" &&
    !(structureSet && ext == ".dcm"))
  {
    error = "cannot write '" + path + "': unknown extension (use " + meshExtensions() +
      (structureSet ? std::string(", or .dcm for an RT structure set") : std::string()) + ")";
    return false;
  }
  const std::string dir = vtksys::SystemTools::GetFilenamePath(path);
  if (!dir.empty() && !vtksys::SystemTools::FileIsDirectory(dir))
  {
    error = "cannot write '" + path + "': folder '" + dir + "' does not exist";
    return false;
  }
  const bool existed = vtksys::SystemTools::FileExists(path, true);
  std::ofstream probe(path, std::ios::app);
  if (!probe)
  {
    error = "cannot write '" + path + "': permission denied or not a file";
    return false;
  }
  probe.close();
  if (!existed)
  {
    std::remove(path.c_str());
  }
  return true;
}

bool checkAllWritable(std::initializer_list<std::string> paths, std::initializer_list<std::string> inputs)
{
  std::string error;
  std::vector<std::string> outputs; // full paths of the outputs before this one
  for (const std::string& path : paths)
  {
    if (path.empty())
      continue;
    const std::string full = vtksys::SystemTools::CollapseFullPath(path);
    for (const std::string& input : inputs)
    {
      if (!input.empty() &&
        (full == vtksys::SystemTools::CollapseFullPath(input) ||
          (vtksys::SystemTools::FileExists(path, true) && vtksys::SystemTools::SameFile(path, input))))
      {
        std::cerr << "error: '" << path << "' is also an input of this run: writing it would destroy '" << input
                  << "'; give the output another name\n";
        return false;
      }
    }
    if (std::find(outputs.begin(), outputs.end(), full) != outputs.end())
    {
      std::cerr << "error: '" << path << "' is named for two outputs: the second would overwrite the first\n";
      return false;
    }
    outputs.push_back(full);
  }
  for (const std::string& path : paths)
  {
    if (!path.empty() && !checkWritable(path, error))
    {
      std::cerr << "error: " << error << "\n";
      return false;
    }
  }
  return true;
}

void Arguments::positional(const std::string& arg, std::string& slot, const char* what)
{
  if (!slot.empty())
  {
    std::cerr << "error: more than one " << what << " given ('" << slot << "', '" << arg << "')\n";
    std::exit(2);
  }
  slot = arg;
}

void Arguments::exclusive(const std::string& arg, std::string& chosen)
{
  if (!chosen.empty() && chosen != arg)
  {
    std::cerr << "error: " << chosen << " and " << arg << " exclude each other: give one\n";
    std::exit(2);
  }
  chosen = arg;
}

long long fileBytes(const std::string& path)
{
  return static_cast<long long>(vtksys::SystemTools::FileLength(path));
}

void* openDisplay()
{
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
    return nullptr;
  for (int attempt = 1; attempt <= 5; ++attempt)
  {
    if (Display* connection = XOpenDisplay(nullptr))
      return connection;
    if (attempt < 5)
      usleep(200000);
  }
  return nullptr;
}

double fieldValue(vtkPolyData* pd, const std::string& name)
{
  vtkDataArray* a = pd->GetFieldData()->GetArray(name.c_str());
  return a ? a->GetTuple1(0) : 0.0;
}

} // namespace lkapp
