#pragma once
/// \file AppSupport.h
/// What the command-line tools share: clean error reporting (VTK errors become
/// one-line messages and a non-zero exit), a text progress bar fed by VTK
/// progress events, and mesh I/O chosen by file extension.

#include <vtkSmartPointer.h>

#include <iosfwd>
#include <initializer_list>
#include <set>
#include <array>
#include <string>
#include <vector>

class vtkLKMedicalImageReader;

class vtkAlgorithm;
class vtkPlaneCollection;
class vtkPolyData;
class vtkRenderWindow;

namespace lkapp
{

/// Makes a crash say where it happened: standard output becomes line-buffered
/// (so that the lines a tool printed before a crash are not lost in a pipe),
/// and a fatal signal (SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT) prints
/// "TOOL: crashed (signal N, NAME)" and the call stack to standard error before
/// the tool dies of that signal as it would have. A write beyond the file
/// size limit (SIGXFSZ) fails and is reported instead. Call first in main.
void installCrashReport(const char* tool);
/// A line the crash report prints last, after the call stack: what the user
/// can still recover (the planner's kept session, with the command that opens
/// it again). An empty note removes it. Safe to call at any time; a note
/// longer than 4,000 bytes is cut.
void setCrashNote(const std::string& note);

/// Routes VTK's messages: errors are collected and printed as "error: ...",
/// warnings as "warning: ..." (quiet or not), pipeline noise is dropped;
/// quiet drops VTK's plain text output. Call once in main.
void installMessageHandler(bool quiet = false);
/// A VTK message as a user reads it: "ERROR: In file, line N\nvtkClass
/// (0x..): message\n\n" gives "message".
std::string cleanMessage(const std::string& text);
/// Updates `algorithm` for a step the run goes on without (a cutting guide
/// beside the cut): its errors are taken, not printed or counted, and the
/// last one is returned, cleaned (empty: none).
std::string updateKeepingErrors(vtkAlgorithm* algorithm);
/// Number of VTK errors since the last call to clearErrors().
int errorCount();
/// Messages of those errors, joined by newlines.
std::string errors();
/// The messages of the errors after the first `count` (a count taken before a
/// step gives that step's errors).
std::string errorsSince(int count);
void clearErrors();
/// Number of VTK warnings so far, and the messages of those after the first
/// `count`: a window shows a step's warnings where the user looks, not only
/// in the terminal.
int warningCount();
std::string warningsSince(int count);

/// A progress bar on standard error, driven by an algorithm's ProgressEvent.
/// It stops where it is at the first VTK error (the error's line ends it), so
/// a failed run never shows 100 %.
class ProgressBar
{
public:
  ProgressBar(vtkAlgorithm* algorithm, const std::string& label, bool enabled = true);
  ~ProgressBar();
  void update(double fraction);
  /// Draws 100 % and ends the line, unless an error stopped the bar.
  void finish();

private:
  std::string label_;
  bool enabled_;
  bool finished_ = false;
  int errorsAtStart_ = 0;
  int lastDrawn_ = -1;
  vtkAlgorithm* algorithm_;
  unsigned long tag_ = 0;
};

/// "pipe" or "device" when `path` is one (neither a file nor a folder),
/// else empty. A pipe nobody writes to blocks whoever opens it, a device may
/// never end (/dev/zero): inputs that are read whole or sought in refuse
/// both; text read as it comes (a session, bash's <(...)) refuses devices.
std::string specialFileKind(const std::string& path);
/// Reads .vtp, .vtk, .stl, .ply or .obj. Returns nullptr and sets error on failure.
/// A coordinate system the file names as 3D Slicer tags it ("SPACE=LPS" or
/// "SPACE=RAS" in a .vtk or .stl header, a .ply or leading .obj comment; the
/// field data "SPACE" of a .vtp) is the mesh's field data "SPACE".
vtkSmartPointer<vtkPolyData> readMesh(const std::string& path, std::string& error);
/// Writes .vtp, .vtk, .stl, .ply, .obj or .gltf (binary where the format allows).
/// The coordinate system `space` ("LPS", "RAS"; when empty, the mesh's own
/// field data "SPACE", if any) is written as 3D Slicer writes and reads it, in
/// every format but glTF, so that Slicer places the model without asking.
/// The file is written whole or not at all (AtomicFile.h): a failed write
/// leaves an earlier file at `path` as it was.
bool writeMesh(vtkPolyData* mesh, const std::string& path, std::string& error, const std::string& space = {});
/// Renders `window` and writes its picture as a PNG file, whole or not at
/// all (AtomicFile.h). False with `error`.
bool writeScreenshot(vtkRenderWindow* window, const std::string& path, std::string& error);
/// The coordinate system a mesh's field data "SPACE" names: "LPS", "RAS" or "".
std::string coordinateSpace(vtkPolyData* mesh);
/// Sets (or, with "", removes) a mesh's field data "SPACE", on a copy of its
/// field data.
void setCoordinateSpace(vtkPolyData* mesh, const std::string& space);
/// The extensions writeMesh accepts, for help texts.
const char* meshExtensions();
/// The formats each cut piece is exported in (pieceN.stl, .vtp, .obj): by
/// the cut's --pieces, the planner's export and the main job, and what
/// removeStaleExports and isExportedFile look for.
inline constexpr std::array<const char*, 3> pieceExtensions{ ".stl", ".vtp", ".obj" };
/// The name, without its extension, of piece `p`'s exported files: "piece1",
/// or for a piece the user named "piece1-" and the name, each run of ASCII
/// characters other than letters, digits, '-' and '.' written as one '_'
/// ("Strut fragment (L)" gives "piece1-Strut_fragment_L"; letters beyond
/// ASCII stay, in UTF-8: "piece1-Unterkieferkörper"; invisible ones, such as
/// a no-break space or a right-to-left mark, do not). A print lab sees
/// the piece's name, as 3D Slicer names exported segments' files; the number
/// keeps two names that differ in case or punctuation apart and the files in
/// the plan's order; no shell or file system takes the name apart.
std::string pieceFileStem(std::size_t p, const std::string& name = std::string());
/// Whether a file's name (no folder) is one an export writes for a piece:
/// "piece", digits, optionally '-' and more, then .stl, .vtp or .obj.
bool isPieceFileName(const std::string& name);
/// Whether a file's name (no folder) is one the planner's export writes for
/// a piece's lattice: "lattice_", a piece's stem (isPieceFileName), ".vtp".
bool isLatticeFileName(const std::string& name);
/// The direction a cutting guide is put on along: its approach (the
/// filter's ApproachUsed, from the bone toward the surgeon) reversed, with
/// rounding's dust (below 5e-4) made 0, so that a report gives no "-0.000".
std::array<double, 3> guideDirection(const double approach[3]);
/// Planes given as (origin, normal) as a vtkPlaneCollection, for a cutting
/// guide's OtherCutPlanes.
vtkSmartPointer<vtkPlaneCollection> planeCollection(const std::vector<std::array<double, 6>>& planes);
/// Whether a file's name (no folder) is one the planner's export writes for
/// a cutting guide: "guide_stroke", digits, ".stl" or ".vtp"; or for two or
/// more joined: "guide_strokes", digits, then "-" and digits once or more,
/// ".stl" or ".vtp".
bool isGuideFileName(const std::string& name);
/// Whether `path` names a file directly in `folder` (both taken as full
/// paths, so "./a/b.vtp" is in "a").
bool isInFolder(const std::string& path, const std::string& folder);
/// Whether `path` names a file that an export into `folder` writes or
/// removes: a piece's file (isPieceFileName), or one of `others` (names in
/// the folder). An input among them would be lost to the export.
bool isExportedFile(const std::string& path, const std::string& folder, std::initializer_list<const char*> others);
/// The files in `folder` whose names `isKind` accepts and that are not among
/// `written`: what an earlier run left of a kind of file this one writes
/// (for removeStaleExports' `others`).
std::vector<std::string> filesNotWritten(
  const std::string& folder, bool (*isKind)(const std::string&), const std::vector<std::string>& written);
/// Removes what an earlier export left in `folder`: every piece file
/// (isPieceFileName) whose stem is not among `pieceStems`, this export's own
/// (pieceFileStem), and the files in `others` (names in the folder) that
/// exist. A re-export with fewer pieces, or with a piece named anew, must not
/// leave the old files beside its own. Nothing else is touched. False with
/// `error` if a file cannot be removed.
bool removeStaleExports(const std::string& folder, const std::vector<std::string>& pieceStems,
  const std::vector<std::string>& others, std::string& error);
/// Size of a file in bytes (0 when it does not exist).
long long fileBytes(const std::string& path);
/// The first value of a field-data array of `pd` (0 when there is none): the
/// filters report their measurements there.
double fieldValue(vtkPolyData* pd, const std::string& name);

/// A connection to the X display DISPLAY names. Debian's VTK renders only
/// through X, and without one it aborts the program in its first render
/// ("bad X server connection"), after the work and before anything can say
/// why; the tools ask for this first. nullptr when DISPLAY is not set or no
/// server accepts (a server that has ended, a host with none, one refusing
/// this client) in 5 tries 0.2 s apart: a running Xvfb refused a connection
/// now and then right after another of the program's had closed. The
/// connection stays open: give it to every render window (SetDisplayId)
/// before its first render, so that neither the window nor VTK 9.1's
/// interactor opens another (the interactor crashes in XSync on a refused
/// one).
void* openDisplay();

/// A box (xmin, xmax, ymin, ymax, zmin, zmax) with each min below its max.
inline bool isOrderedBox(const double v[6])
{
  return v[0] < v[1] && v[2] < v[3] && v[4] < v[5];
}

/// Command-line helpers.
bool parseDouble(const std::string& text, double& value);
bool parseInt(const std::string& text, long& value);
bool parseTriple(const std::string& text, double v[3]);
/// Exactly `n` numbers, separated by commas or spaces.
bool parseNumbers(const std::string& text, double* v, int n);

/// Walks a command line. Every method that reads an option's value exits
/// with status 2 and a one-line message when the value is missing or wrong,
/// so each tool states only its options and their ranges.
class Arguments
{
public:
  using Usage = void (*)(std::ostream&);
  Arguments(int argc, char* argv[], Usage usage);
  /// The next argument, or false at the end. -h / --help prints the usage and exits 0.
  bool next(std::string& arg);
  /// The value after option `arg`. An option given a value more than once
  /// takes the last, with a warning that says so (a script's defaults
  /// followed by the user's are then seen to be overridden).
  std::string value(const std::string& arg);
  /// An integer value in [lo, hi].
  long integer(const std::string& arg, long lo, long hi, const char* what);
  /// A finite number in [lo, hi].
  double number(const std::string& arg, double lo, double hi, const char* what);
  /// A label value (a whole number, 1 or more: `label`, `name` emptied) or a
  /// segment's name (anything else, "3rd molar" too: `name`, `label` 0).
  void labelOrName(const std::string& arg, long& label, std::string& name);
  /// Three numbers X,Y,Z.
  void triple(const std::string& arg, double v[3]);
  /// A box XMIN,XMAX,YMIN,YMAX,ZMIN,ZMAX, each min below its max.
  void box(const std::string& arg, double v[6]);
  /// Stores a positional argument in `slot`; exits 2 with "more than one
  /// WHAT given" when the slot is already taken.
  void positional(const std::string& arg, std::string& slot, const char* what);
  /// Records `arg` as the option taken from a group of options that
  /// exclude each other (`chosen`, empty before the first); exits 2 with
  /// "--all and --seed exclude each other" when another of the group was
  /// given (the same one twice is fine).
  void exclusive(const std::string& arg, std::string& chosen);
  /// Exits 2 for an option the tool does not know.
  [[noreturn]] void unknown(const std::string& arg);
  /// True for an argument that looks like an option.
  static bool isOption(const std::string& arg) { return !arg.empty() && arg[0] == '-'; }

private:
  int argc_;
  char** argv_;
  int i_ = 0;
  Usage usage_;
  std::set<std::string> given_; ///< the options given a value so far
};

/// Why --iso was not used, for a volume taken as a label map at 0.5 (the
/// surface is not the one --iso asked for): "--iso 200 is not used: label 2
/// of 'seg.nrrd' is taken as a 0/1 label map, at 0.5" (`label` > 0), or
/// "... 'mask.nrrd' is a 0/1 label map, taken at 0.5", and where the tool has
/// --no-label-map (`noLabelMapOption`), how to take it at --iso instead.
std::string unusedIsoNote(double iso, int label, const std::string& input, bool noLabelMapOption);

/// The smoothing a surface was made with, in words: "a Gaussian of 0.5 voxel
/// on the volume, 20 windowed-sinc iterations on the surface" (either part
/// alone where the other is none), or "no smoothing"
/// (vtkLKBoneSurfaceFilter's effective ImageSmoothing and SmoothingIterations).
std::string smoothingWords(double imageSmoothing, int iterations);

/// --label NAME on a DICOM CT, whose volume names no segments, where an RT
/// structure set drawn on that CT lies in its folder (the reader lists them)
/// with an ROI of that name (matched as vtkLKBoneSurfaceFilter matches names:
/// exactly, else in any case): `reader` reads that set's file instead, and
/// `note` says so; true. False with `error` when several sets have the ROI
/// (it names their files) or the set cannot be read; false with `error`
/// empty when there is nothing to take (the reader is left as it was).
bool readOrganFromStructureSet(
  vtkLKMedicalImageReader* reader, const std::string& name, std::string& note, std::string& error);

/// False (with error set) if the mesh file cannot be created or has an
/// unknown extension: checked before a long run, so that the run does not
/// end in a lost result. `structureSet`: .dcm (an RT structure set) is a
/// known extension too.
bool checkWritable(const std::string& path, std::string& error, bool structureSet = false);

/// checkWritable for every non-empty path; prints "error: ..." for the first
/// that fails and returns false. An output that is one of the `inputs` (the
/// same file, by any path), or that two outputs share, fails too: writing it
/// would destroy a file the run reads, or the other output.
bool checkAllWritable(std::initializer_list<std::string> paths, std::initializer_list<std::string> inputs = {});

} // namespace lkapp
