// The planner's sessions: what a surgeon did in latticekit-planner (strokes,
// the cut, the lattice, Metro, the moved segment, deformations, how a CT's
// surface was made), saved with `w` and replayed with --replay. A session is
// a JSON object. Every top-level field may be left out (the defaults below);
// a deformation needs its piece, centre and radius, and bump and box their
// normal and amount:
//
//   "strokes":  [{"mode": "paint" | "nearest" | "snap" | "split",
//                 "points": [[x, y, z], ...],         patient mm, on the surface
//                 "saw": {"origin": [x, y, z],        a saw line (split mode): its
//                         "normal": [x, y, z]},       plane; the points are the
//                                                     bone's section there
//                 "guideOtherSide": bool}, ...]       a saw line's guide on the
//                                                     side other than the rest's
//   "cut": bool, "capping": bool (default true)       the closed lines cut, capped
//   "lattice": bool, "latticeVertices": 4 to 1e8      a lattice per piece (600)
//   "metro": bool                                     Metro colours on the lattices
//   "mirror": bool                                    the bone's mirror image across its
//                                                     plane of symmetry, and the segment's
//                                                     distance to it
//   "guides": bool                                    a cutting guide for each saw line
//   "guidesOtherSide": bool                           on the bone's other side (inner)
//   "guidesJoined": bool                              the guides of the saw lines
//                                                     joined along the bone (each to
//                                                     the next across one piece) by
//                                                     bars: resection guides
//   "mirrorPlane": [[x, y, z], [x, y, z], [x, y, z]]  the plane to mirror across, set by
//                                                     three points (midline landmarks;
//                                                     none: the fitted plane)
//   "scanOnLine": k                                   the scan (CT) on cut line k's plane
//                                                     (the plan's numbering; 0: none)
//   "scanAcross": bool                                across the line, not on its plane
//   "scanWindow": "bone" | "soft tissue"              its window (bone)
//   "scanWindowLevel": [width > 0, level]             a window set by hand (the
//                                                     view dragged), in place of
//                                                     scanWindow's (none)
//   "scanOffset": -200 to 200                         the view's plane moved along
//                                                     its normal, mm toward the
//                                                     viewer (the wheel; 0)
//   "segment": {"piece": i, "matrix": [16 numbers],   the moved piece, row-major 4x4,
//               "at": [x, y, z]}                      and a point of it (see below)
//   "deformations": [{"tool": "bump" | "box" | "smooth", "piece": i,
//                     "centre": [x, y, z], "radius": r > 0,
//                     "normal": [x, y, z], "amount": k,   (bump, box)
//                     "falloff": a >= 0,                  (bump; ln(100) / r^2)
//                     "iterations": 1 to 100,             (smooth; 3)
//                     "stroke": n >= 1}, ...]             (smooth: its brush stroke)
//   "names": [{"name": text, "at": [x, y, z]}, ...]   names given to pieces (see
//                                                     PieceName)
//   "measurements": [{"from": [x, y, z],              distances and angles
//                     "to": [x, y, z],                measured (see Measurement)
//                     "at": [x, y, z],                an angle's vertex (none: a
//                                                     distance)
//                     "pieces": [i, j(, k)]}, ...]    from's, to's (and at's)
//                                                     pieces (optional)
//   "surface": {"iso": HU, "seed": [x, y, z],
//               "crop": [xmin, xmax, ymin, ymax, zmin, zmax], "series": i,
//               "close": bool,                      closed at the scan's border
//               "smooth": 0 to 1000,                windowed-sinc iterations (0)
//               "image_smooth": 0 to 20,            the Gaussian on the volume, in voxels;
//                                                   both as used (saved since December
//                                                   2026; without image_smooth a label
//                                                   map's is one voxel, as it was then)
//               "label": 1 or more | "name"}        one label of a label map, or a
//                                                   segment by name (none)
//   "patient": {"head": [x, y, z],                  for a scan whose file gives no
//               "front": [x, y, z]}                 orientation: where the patient's head
//                                                   and face point in its coordinates (the
//                                                   CT view stands head up, the first view
//                                                   from the front; none)
//   "input": {"file": name,                       what the session was drawn on: the
//             "bounds": [6 numbers]}              file (no folders) and the bone's
//                                                 bounds; a replay on another says so
//
// Pieces are numbered in cut order. After a changed cut the segment becomes
// the piece nearest its "at" point, and each deformation the piece whose
// surface is nearest its centre (its own when that is as near).
//
// A field of the wrong kind is refused with a message that names it; a field
// the planner does not know (misspelt, or a newer planner's) is ignored, and
// the replay names it among its messages.
#ifndef latticekit_apps_PlannerSession_h
#define latticekit_apps_PlannerSession_h

#include "common/ScanOnPlane.h"
#include "vtkLKStrokeFeatureLineFilter.h"
#include "vtkLKText.h"

#include <vtk_jsoncpp.h>

#include <array>
#include <string>
#include <vector>

namespace lkplanner
{
struct Stroke
{
  int mode = vtkLKStrokeFeatureLineFilter::NEAREST_EDGES;
  std::vector<std::array<double, 3>> points;
  /// A saw line's plane (split mode): the cut follows the bone's section by
  /// it, traced again on the bone at every replay (the loop through the
  /// first point, or nearest it), so the cut stays flat on a surface made
  /// again with other settings. The points are the section when it was drawn.
  bool saw = false;
  std::array<double, 3> sawOrigin{ 0, 0, 0 }, sawNormal{ 0, 0, 1 };
  /// A saw line's cutting guide on the side other than the rest's (K with
  /// the mouse on it): the side the filter chooses, or with
  /// Session::guidesOtherSide its other side, reversed for this guide alone.
  bool guideOtherSide = false;
};

/// One deformation of the adaptive micro planar patches (seed 002) on a
/// piece, in the piece's own frame (before the segment's move).
/// - bump: eq. 1, k exp(-a d^2) along the surface normal within `radius` of
///   the centre; k = amount, a = falloff (the tool uses ln(100) / radius^2,
///   so the bump has fallen to 1 % of k at the radius);
/// - box: every vertex in the cube centre +- radius moves by amount * normal
///   (the paper's range deformation);
/// - smooth: eq. 2 in the ball (centre, radius), `iterations` times (one dab
///   of the smoothing brush); `stroke` numbers the brush stroke it belongs
///   to (1, 2, ...; the dabs of one stroke share it), 0 where it is not
///   known (a session written before it was kept).
struct Deformation
{
  std::string tool = "bump";
  int piece = 0;
  std::array<double, 3> centre{ 0, 0, 0 }, normal{ 0, 0, 1 };
  double amount = 0.0, radius = 1.0, falloff = 0.0;
  int iterations = 3;
  int stroke = 0;
};

/// A name a surgeon gave a piece (`t` in the window), for the export: the
/// structure set's ROI and the plan. It names the piece whose surface is
/// nearest `at` (a point picked on it, before deformations and the
/// segment's move), so it stays with that piece when the cut numbers the
/// pieces anew; of two names on one piece the later holds.
struct PieceName
{
  std::string name;
  std::array<double, 3> at{ 0, 0, 0 };
};

/// A distance the surgeon measured (u, two clicks): two points picked on
/// the bone or on the CT view's plane, patient mm, each in its piece's own
/// frame (before the segment's move, as a name's point and a deformation's
/// centre), and the piece each was picked on. An end on the moved segment
/// moves with it, so a distance from the segment to the bone beside it
/// follows the move. Each end goes with the piece nearest it when the cut
/// numbers the pieces anew (its own when that is as near: a point on a cut
/// line lies on both); an end of the soft tissue (-1) goes with none; an
/// end not resolved yet (no "pieces" in an older session) takes the
/// nearest.
///
/// An angle (a, three clicks: an arm's end, the vertex, the other arm's
/// end) is the angle at `at` between the arms to `from` and `to`; its
/// vertex follows its piece as the ends do.
struct Measurement
{
  enum End
  {
    FROM = 0,
    TO = 1,
    AT = 2
  };
  std::array<double, 3> from{ 0, 0, 0 }, to{ 0, 0, 0 };
  bool angle = false;
  std::array<double, 3> at{ 0, 0, 0 };
  /// An end's piece not known yet (a session without "pieces"): the
  /// nearest piece takes it.
  static constexpr int kUnresolved = -2;
  /// An end with no piece: a point of the soft tissue, measured on the CT,
  /// which the plan does not move.
  static constexpr int kSoftTissue = -1;
  /// The pieces of from, to and at (kSoftTissue: none).
  std::array<int, 3> pieces{ kUnresolved, kUnresolved, kUnresolved };
  /// Its points (from, to; at for an angle) as picked.
  std::vector<std::array<double, 3>> points() const;
  /// The distance between the points as picked (the segment not moved).
  double length() const;
  /// The angle's degrees as picked (0 to 180).
  double degrees() const;
};

/// The angle at `at` between the arms to a and b, in degrees (0 to 180); NaN
/// where an arm has no length.
double angleAt(const std::array<double, 3>& a, const std::array<double, 3>& at, const std::array<double, 3>& b);

/// The longest name: a DICOM ROIName (LO) holds 64 characters, and the moved
/// segment's gets " (moved)" (8).
constexpr std::size_t kPieceNameLength = lkvtk::kDICOMLongStringLength - 8;

/// Whether `name` can name a piece: UTF-8 text of 1 to kPieceNameLength
/// characters, no control character, no backslash (DICOM's value
/// separator), not starting or ending with a space; else `why` says what is
/// wrong. The structure set spells it in the CT's character set, or in UTF-8
/// where that one cannot.
bool validPieceName(const std::string& name, std::string& why);

/// The lattices' vertices per piece a session (and the L key) may ask for.
inline constexpr long kFewestLatticeVertices = 4, kMostLatticeVertices = 100000000;
inline constexpr const char* kLatticeVerticesRange = "a whole number from 4 to 100,000,000";

struct Session
{
  std::vector<Stroke> strokes;
  bool cut = false;
  bool capping = true;
  bool lattice = false;
  long latticeVertices = 600;
  bool metro = false;
  /// The bone's mirror image across its plane of symmetry, shown as the
  /// template of mirror-image planning (o).
  bool mirror = false;
  /// A cutting guide for each saw line (k): a shell on the bone across the
  /// saw's plane with a slot for the blade (vtkLKCuttingGuideFilter).
  bool guides = false;
  /// The guides on the other side of the bone (K): the side the filter
  /// chooses (a mandible's outer side) reversed.
  bool guidesOtherSide = false;
  /// The guides of the saw lines joined along the bone, each line to the
  /// next either side of one piece of the cut (lkapp::chainLinesByPiece), by
  /// bars over the bone between them (j): a resection guide for each chain,
  /// one part to print (vtkLKGuideBarFilter).
  bool guidesJoined = false;
  /// The scan on cut line k's plane (c), k from 1 (the plan's numbering of
  /// the cut lines); 0: not shown.
  int scanOnLine = 0;
  /// Across that line (the bone along its length, the cut planes as lines),
  /// not on its plane.
  bool scanAcross = false;
  /// The CT shown in the soft-tissue window (C), not the bone window.
  bool softTissueWindow = false;
  /// A window set by hand (the view dragged; width > 0), in place of the
  /// preset's; width 0: none.
  double scanWindowWidth = 0.0, scanWindowLevel = 0.0;
  /// The view's plane moved along its normal, mm toward the viewer (the
  /// mouse wheel over the view): the planes beside the cut.
  double scanOffset = 0.0;
  /// Three points of the bone (midline landmarks, in its frame before any
  /// move) that set the plane to mirror across (O, three clicks); empty: the
  /// bone's fitted plane of symmetry.
  std::vector<std::array<double, 3>> mirrorPlane;
  /// The moved segment: a piece index (pieces in cut order) and its rigid
  /// transform, row-major 4x4 (the surgery moves the segment).
  int segment = -1;
  std::array<double, 16> segmentMatrix{ 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  /// A point of the segment's surface (before its move), kept when it is
  /// picked: pieces are numbered in cut order, and a changed cut can number
  /// them anew, so the segment follows the piece nearest this point.
  bool segmentAnchored = false;
  std::array<double, 3> segmentAnchor{ 0, 0, 0 };
  /// Applied in order to the pieces after the cut, before the lattice.
  std::vector<Deformation> deformations;
  std::vector<PieceName> names;
  std::vector<Measurement> measurements;
  /// How a CT's bone surface was made (saved with the session, so that its
  /// strokes find the same surface on replay): the threshold, the component
  /// at a seed or the largest, the DICOM series.
  struct Surface
  {
    bool given = false; ///< false: none recorded (a mesh input, an older session)
    double iso = 300.0;
    bool seeded = false;
    std::array<double, 3> seed{};
    bool cropped = false;
    std::array<double, 6> crop{}; ///< patient coordinates, xmin, xmax, ymin, ymax, zmin, zmax
    bool closed = false; ///< closed where the scan's border cuts bone (a crop always is)
    long series = -1; ///< -1: the largest
    /// Windowed-sinc iterations on the surface (negative: the bone filter's
    /// own, 20 for a label map and none for a CT).
    long smoothing = -1;
    /// Gaussian standard deviation on the volume, in voxels (negative: the
    /// bone filter's own, 0.5 voxel for a label map and none for a CT).
    double imageSmoothing = -1.0;
    /// A session saved before December 2026 names neither when they were the
    /// defaults: a label map's were then a Gaussian of one voxel and no
    /// smoothing of the surface, and its strokes lie on that surface.
    bool labelMapDefaultsOfBefore = false;
    long label = 0; ///< one label of a label map with several (0: none)
    std::string labelName; ///< or a 3D Slicer segmentation's segment by name
  } surface;
  /// For a scan whose file gives no orientation: the patient's head and
  /// front in its coordinates (--head, --front).
  bool patientGiven = false;
  lkapp::HeadAndFront patient;
  /// What the strokes were drawn on: the input's file name (no folders) and
  /// the bone's bounds, so that a replay on another scan (another patient's,
  /// or the same file made into another surface) can say so.
  std::string inputFile;
  bool inputBoundsKnown = false;
  std::array<double, 6> inputBounds{};
};

/// A point as a JSON list [x, y, z].
Json::Value triple(const std::array<double, 3>& v);

/// What one stroke is (its mode, points and saw plane), as a key that
/// changes when it does.
std::string strokeKey(const Stroke& st);

/// The part of a session the cut depends on (strokes, cut, capping), as a
/// key that changes when they do.
std::string cutKey(const Session& s);

/// The bump tool's eq. 1 falloff a: the bump is down to 1 % of k at the radius.
double bumpFalloff(double radius);

/// A stroke mode's name in a session ("paint", "nearest", "snap", "split"),
/// and back (an unknown name reads as "nearest"; readSession refuses it).
const char* modeName(int mode);
int modeOf(const std::string& name);

/// The JSON text of `s`, as saveSession writes it.
std::string sessionText(const Session& s);

/// Writes `s` to `path` as JSON; false with `error` if it cannot.
bool saveSession(const Session& s, const std::string& path, std::string& error);

/// Where a session left unsaved at quitting is kept: `sessionPath` with
/// "-unsaved" before its extension (planner_session-unsaved.json).
std::string unsavedSessionPath(const std::string& sessionPath);

/// The plane through three points: their centroid and unit normal, turned
/// to the patient's left (x >= 0, as the fitted plane is). False, with
/// `why`, when the points are nearly in a line (the smallest angle of their
/// triangle under 2 degrees), or not finite.
bool planeThrough(const std::vector<std::array<double, 3>>& points, std::array<double, 3>& origin,
  std::array<double, 3>& normal, std::string& why);

/// Reads a session, every field's kind checked (a wrong one is refused with
/// a message naming it and `path`, not an exception). Fields it does not
/// know (misspelt, or a newer planner's) are ignored and, with `notes`,
/// named there, one line per object.
bool readSession(const Json::Value& root, const std::string& path, Session& s, std::string& error,
  std::string* notes = nullptr);

/// Reads the file `path` (a JSON object) into `s`.
bool loadSession(const std::string& path, Session& s, std::string& error, std::string* notes = nullptr);
} // namespace lkplanner

#endif
