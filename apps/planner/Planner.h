#pragma once
/// \file Planner.h
/// latticekit-planner's plan and scene: the bone, the session
/// (PlannerSession.h), and what is rebuilt from them: the feature lines, the
/// cut pieces, their deformations, each piece's lattice and Metro colours,
/// the actors, the status line, the report, the export and the screenshot.
/// The window's mouse and keys are PlannerStyle.h; the command line is
/// apps/latticekit-planner.cxx. The class is defined in Planner.cxx (the
/// scene, the status, the plan's text) and, one concern each, in
/// PlannerCut.cxx, PlannerDeformations.cxx, PlannerLattices.cxx,
/// PlannerMeasurements.cxx, PlannerNames.cxx, PlannerMirror.cxx, PlannerGuides.cxx,
/// PlannerScanView.cxx and PlannerExport.cxx.

#include "common/CutReport.h"
#include "common/KeyComposer.h"
#include "common/PieceContact.h"
#include "common/ScanPicture.h"
#include "planner/PlannerSession.h"

#include "vtkLKCuttingGuideFilter.h"
#include "vtkLKGuideBarFilter.h"
#include "vtkLKPatchDeformationFilter.h"
#include "vtkLKStrokeFeatureLineFilter.h"

#include <vtkActor.h>
#include <vtkActor2D.h>
#include <vtkLookupTable.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderWindow.h>
#include <vtkAnnotatedCubeActor.h>
#include <vtkAxesActor.h>
#include <vtkCaptionActor2D.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTransform.h>

#include <algorithm>
#include <array>
#include <memory>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

class vtkAlgorithmOutput;

namespace lk
{
class ClosestPointTree;
}

namespace lkplanner
{

/// The keys, as the window's help text and --help list them.
extern const char* const kHelp;

/// The planner's deformation tools, in the order `f` cycles through them.
enum Tool
{
  NO_TOOL,
  BUMP,
  BOX,
  SMOOTH,
  TOOL_COUNT
};

/// The name of a Tool, as the status line shows it.
const char* toolName(int tool);

/// The colour of piece p (four colours, repeated).
std::array<double, 3> pieceColour(std::size_t p);

/// The plan and its scene. rebuild() redoes, from the bone and the session,
/// what changed: the strokes and the cut only when they changed, each
/// piece's lattice only when that piece did.
class Planner
{
public:
  vtkSmartPointer<vtkPolyData> bone;
  /// The CT or mesh file the bone came from (its full path): the exported plan names it.
  std::string input;
  /// A file of the DICOM CT series the bone came from (the reader's
  /// ReferenceImageFileName), or empty: the export then writes the pieces as
  /// an RT structure set on that CT.
  std::string referenceImage;
  /// What the last export wrote beside the meshes (the structure set), for
  /// the batch report and the window's notice; empty when nothing.
  std::string exportNote;
  bool exportedStructureSet = false; ///< the last export wrote pieces.dcm
  Session session;
  int mode = vtkLKStrokeFeatureLineFilter::NEAREST_EDGES;
  bool drawing = false;
  bool sawing = false; ///< the mouse draws saw lines (straight, across the bone)
  std::vector<std::array<double, 3>> current;
  /// How near a drag must start to an open line's end to continue it: twice
  /// the bone's mean edge length, the stroke filter's tolerance for a stroke
  /// whose ends meet (set by setup()).
  double joinTolerance = 1.0;
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkRenderWindow> window;
  /// The patient's sides in the top right corner (a cube whose faces say L,
  /// R, A, P, S, I), turned with the view; shown only when the bone's
  /// coordinate system is known (its SPACE tag: an oriented CT, or a tagged
  /// mesh file).
  vtkNew<vtkRenderer> markerRenderer;
  /// The measurements, drawn over the bone (a distance's line runs through
  /// it), with the main view's camera.
  vtkNew<vtkRenderer> overlay;
  vtkNew<vtkAnnotatedCubeActor> marker;
  vtkNew<vtkAxesActor> markerAxes; ///< arrows to the patient's left (or right), back (or front) and top
  vtkNew<vtkTextActor> help, status, messages;
  vtkNew<vtkScalarBarActor> scalarBar;
  vtkNew<vtkLookupTable> distanceColours; ///< the Metro colours of every piece
  vtkNew<vtkActor> strokeActor;
  vtkNew<vtkPolyData> strokePd;
  vtkNew<vtkActor2D> sawActor; ///< the saw line being dragged, on the screen
  vtkNew<vtkPolyData> sawPd;
  std::vector<vtkSmartPointer<vtkActor>> sceneActors;
  std::vector<vtkSmartPointer<vtkPolyData>> pieces;
  std::string message; ///< a problem: shown, and reported as "message:" in batch runs
  /// In a window a user works in: every step first shows "working ..." on
  /// the status line (a cut, lattices or Metro colours take seconds, and the
  /// window would stand still without a word).
  bool showWork = false;
  /// What the input and a replay warn of: the scan's reader and the bone
  /// surface (slices missing or unevenly spaced, several series, no patient
  /// orientation), a session drawn on another input (checkReplayedInput),
  /// fields a replay ignored. Kept at the top of every message and in the
  /// exported plan.
  std::string inputWarnings;
  /// The session as it was last replayed, saved ('w') or exported ('e').
  std::string savedSession;
  /// Where the session is kept while it differs from savedSession (empty:
  /// nowhere), and what was last written there (empty while it does not
  /// differ).
  std::string unsavedPath, keptSession;
  /// After a save or an export: this session is the saved one, and the kept
  /// copy goes.
  void markSaved();
  /// Writes the session to unsavedPath if it differs from savedSession (and
  /// removes the file once it no longer does). False, with `error`, if the
  /// file cannot be written.
  bool keepUnsaved(std::string& error);
  /// keepUnsaved after a step, a failure said in the window's message.
  /// rebuild() calls it, and so does every step that changes the session
  /// without one (the segment picked, moved or reset), so a crash loses at
  /// most the step that crashed.
  void keepChanges();
  std::string notice;  ///< an outcome (saved, exported): shown only
  bool cutFailed = false;
  bool moving = false;                    ///< the mouse moves the segment
  int tool = NO_TOOL;                     ///< the deformation tool the mouse uses
  double radius = 1.0;                    ///< the tool's radius (set from the bone's size)
  vtkNew<vtkActor> preview;               ///< the piece being deformed, live
  std::vector<double> frameMs, updateMs;  ///< per mouse move: deformation plus render, deformation alone
  std::vector<Session> undoStack, redoStack; ///< whole-session snapshots
  std::vector<std::vector<vtkSmartPointer<vtkActor>>> pieceActors;
  /// Each piece's lattice and its surface, kept while the piece and the
  /// vertex count do not change: toggling Metro, a stroke that leaves the
  /// cut as it was or a deformation of another piece refits nothing.
  struct FittedLattice
  {
    std::uint64_t key = 0;
    vtkSmartPointer<vtkPolyData> lattice, surface; ///< empty surface: the fit failed
    std::string errors;
    /// The lattice edges that keep the lines (chords through the points of
    /// the lines kept within kLineTolerance), and the lines' edges a
    /// deformation refined (no longer edges of the piece: not kept).
    std::size_t featureEdges = 0, featureEdgesRefined = 0;
    /// Those lattice edges that are creases of the surface: on lines across
    /// which the piece bends sharply (a cut's rim; vtkLKLatticeFitFilter's
    /// CreaseAngle).
    std::size_t creaseEdges = 0;
    /// The vertices of those lines, how many of them hold the lines within
    /// kLineTolerance, and how many the lattice keeps (those, and any whose
    /// collapse along its line would have folded it); whether the needed
    /// ones raised the count above the session's (to twice theirs, so the
    /// rest of the bone keeps as many).
    std::size_t lineVertices = 0, neededLineVertices = 0, keptLineVertices = 0;
    bool raised = false;
    /// The surface with its Metro distance to the piece, once asked for.
    vtkSmartPointer<vtkPolyData> metro;
    double colourMaximum = 0.0, hausdorff = 0.0;
  };
  std::vector<FittedLattice> lattices;
  /// Under the status line, after a cut: each cut line's length, the
  /// distance and angle between two lines, each piece's volume.
  std::string cutSummary;
  /// How the moved segment meets each other piece as the view shows it
  /// (placeSegment's matrix, during a drag too): {piece, contact}, empty
  /// when the segment is not moved. The pieces' contact surfaces are built
  /// once per set of pieces shown.
  std::vector<std::pair<int, lkapp::Contact>> contacts;
  std::vector<std::unique_ptr<lkapp::ContactSurface>> contactSurfaces;
  std::vector<vtkPolyData*> contactPieces; ///< what contactSurfaces were built on
  void updateContacts(const std::array<double, 16>& matrix);
  /// Where the moved segment and another piece run through each other: red
  /// points on the vertices of either inside the other, over the bone.
  vtkNew<vtkActor> overlapMarker;
  /// The status line's word on them: the deepest overlap, or the nearest
  /// piece's gap.
  std::string contactStatus() const;
  std::size_t latticeFits = 0, latticesReused = 0;

  /// The bone's mirror image across its plane of symmetry (o, the session's
  /// "mirror"): the template of mirror-image planning, the healthy side
  /// mirrored onto the other, found once per bone (vtkLKSymmetryPlaneFilter)
  /// and shown translucent over it.
  struct MirrorImage
  {
    bool made = false;                    ///< asked for (made or failed) ...
    std::vector<std::array<double, 3>> madeWith; ///< ... with this set plane (empty: fitted)
    vtkSmartPointer<vtkPolyData> surface; ///< null when it could not be made (error)
    std::shared_ptr<const lk::ClosestPointTree> tree; ///< distances to it (CGAL's AABB tree)
    std::array<double, 3> origin{ 0, 0, 0 }, normal{ 0, 0, 0 };
    double mean = 0.0, largest = 0.0; ///< from the bone's points to it
    double kept = 0.0; ///< the share of the bone's points the plane was fitted to
    std::string error;
  } mirror;
  /// The mirror image, made on first use.
  const MirrorImage& mirrorImage();
  vtkNew<vtkActor> mirrorActor;
  /// The plane of symmetry over the bone's extent: a faint sheet and its
  /// outline, for the surgeon to judge it by (a mid-sagittal plane runs
  /// between the incisors and the condyles).
  vtkNew<vtkActor> mirrorPlaneActor, mirrorPlaneOutline;
  /// How far the segment's surface (its caps left out: the mirror has none
  /// there) is from the mirror image: mean and largest over its vertices,
  /// where `matrix` puts it and where it was cut (`before`). Set by
  /// updateMirrorFit, with the mirror shown and a segment.
  struct MirrorFit
  {
    bool valid = false;
    double mean = 0.0, largest = 0.0;
  };
  MirrorFit segmentToMirror, segmentToMirrorBefore;
  /// The piece (and its modification time) segmentToMirrorBefore and
  /// mirrorFitVertices are of, the latter its vertices of the bone's own
  /// surface (its caps' left out): a drag measures only the moved fit.
  vtkPolyData* mirrorFitPiece = nullptr;
  vtkMTimeType mirrorFitTime = 0;
  std::vector<vtkIdType> mirrorFitVertices;
  MirrorFit mirrorFitOf(const std::array<double, 16>& matrix) const;
  void updateMirrorFit(const std::array<double, 16>& matrix);
  /// The angle (degrees) between a plane's normal and x, the patient's
  /// left-right axis: how far a plane is from mid-sagittal.
  static double degreesFromX(const std::array<double, 3>& normal);
  /// The plan's lines on the mirror image (empty when it is not shown).
  std::string mirrorText() const;

  /// The cutting guides (k, the session's "guides"): one per saw line, on
  /// the bone as scanned (before the cut, deformations and the segment's
  /// move), made by vtkLKCuttingGuideFilter and kept while the bone and
  /// that saw line's plane stay.
  struct CuttingGuide
  {
    std::size_t stroke = 0;                        ///< the saw line's stroke, from 0
    std::array<double, 3> origin{}, normal{};      ///< its plane, as the guide was made on it
    bool otherSide = false;                        ///< on the side the filter does not choose
    /// The planes of the saw lines near it (origin, normal), which its label
    /// and screw holes keep clear of (the filter's OtherCutPlanes).
    std::vector<std::array<double, 6>> others;
    /// The filter that made it: its settings and what it measured (the
    /// approach, the slot's length, the contact, the volume, the holes).
    vtkSmartPointer<vtkLKCuttingGuideFilter> filter;
    vtkSmartPointer<vtkPolyData> surface;          ///< null when it could not be made (error)
    std::string error;
    std::string warning; ///< what the filter warned of (its label left out)
  };
  std::vector<CuttingGuide> guides;
  vtkPolyData* guidesBone = nullptr; ///< the bone (and its time) the guides were made on
  vtkMTimeType guidesBoneTime = 0;
  vtkNew<vtkActor> guideActor;
  /// Makes the guides the session asks for (anew only where a saw line or
  /// the bone changed), shows them and says in `message` why one failed.
  void updateGuides();
  /// Joins the guides along the bone when the session asks (anew only where
  /// a guide changed), and says in `message` why a guide stays apart.
  void updateJoinedGuides();
  /// The plan's lines on the guides (empty when they are not shown).
  std::string guidesText() const;
  /// "guide_stroke<n>", the stem of a guide's files (n from 1).
  static std::string guideFileStem(std::size_t stroke);
  /// The resection guides (j, the session's "guidesJoined"): the guides of
  /// the saw lines joined along the bone, each line to the next across one
  /// piece of the cut (lkapp::chainLinesByPiece: as they lie along the bone,
  /// not as they were drawn; without a cut, in pairs in stroke order), by
  /// bars over the bone between them (vtkLKGuideBarFilter) into one part for
  /// each chain; made anew only when one of its guides was.
  struct JoinedGuide
  {
    std::vector<std::size_t> members; ///< its guides, indices into `guides`, in their order along the bone
    std::vector<vtkSmartPointer<vtkPolyData>> made; ///< the guides' surfaces it was made of
    vtkSmartPointer<vtkLKGuideBarFilter> filter;    ///< its bars' settings and sizes
    vtkSmartPointer<vtkPolyData> surface; ///< null when it could not be made (error)
    std::string error;
  };
  std::vector<JoinedGuide> joinedGuides;
  /// Every part tried at the last update (joined or not; lkapp::joinChain
  /// tries a chain's neighbours alone where the whole cannot be joined),
  /// kept so that the next update makes anew only what changed.
  std::vector<JoinedGuide> joinAttempts;
  /// "1, 3 and 2": the strokes of a joined guide's lines, in its order.
  std::string joinedStrokes(const JoinedGuide& joined, const std::string& separator = ", ",
    const std::string& last = " and ") const;
  /// The joined guide made with guides[i], or null (apart, or the join
  /// failed).
  const JoinedGuide* joinedGuideOf(std::size_t i) const;
  /// A part to print: a joined guide (one part), or a guide joined to none.
  struct GuidePart
  {
    vtkPolyData* surface = nullptr;
    std::string stem;    ///< its files' stem: guide_strokeN, guide_strokesN-M(-K...)
    std::string roiName; ///< its ROI in the exported structure set
  };
  /// The guides made, as they are printed: the joined pairs, then the
  /// guides joined to none (shown, exported as files and as ROIs alike).
  std::vector<GuidePart> guideParts() const;
  /// "guide_strokes<n>-<m>", the stem of a joined guide's files (its saw
  /// lines' strokes, from 1).
  std::string joinedGuideFileStem(const JoinedGuide& joined) const;

  /// The scan the bone surface was made from, in its data coordinates, and
  /// the matrix to the bone's (patient) coordinates; null for a mesh file.
  /// A CT whose organ came from an RT structure set is the CT itself.
  vtkSmartPointer<vtkImageData> scan;
  vtkNew<vtkMatrix4x4> scanToPatient;
  bool scanIsLabelMap = false;
  /// A file of the CT a segmentation input (a DICOM SEG, an RT structure
  /// set) was drawn on, when it lies beside it: read in place of `scan` the
  /// first time the view needs it (readScanFile).
  std::string scanFile;
  /// Reads scanFile into scan (once); false, with why, when it cannot.
  bool readScanFile(std::string& why);
  /// Whether there is a scan to show (or one to read).
  bool hasScan() const { return scan || !scanFile.empty(); }
  /// The scan on a cut line's plane (c, the session's scanOnLine), in the
  /// window's lower left corner, above the status lines.
  vtkNew<vtkRenderer> scanRenderer;
  /// The numbers of the closed cut lines (from 1, the plan's numbering).
  std::vector<int> closedCutLines() const;
  /// The picture of the scan on cut line `number`'s plane, or across it
  /// (the other lines' planes drawn where they cross it), without the moved
  /// segment (movedSection); false with why.
  /// `offset`: the plane moved along its normal, mm toward the viewer (the
  /// session's scanOffset; the export's pictures are on the cut's own plane).
  bool scanPictureOf(int number, bool across, double offset, lkapp::ScanPicture& picture, std::string& why);
  /// "CT on cut line 1's plane", "label map across cut line 2".
  std::string scanText(int number, bool across) const;
  /// The picture's title: scanText and where its plane lies against the
  /// cut's (the picture writes its window itself).
  std::string scanTitle(const lkapp::ScanPicture& picture, int number, bool across, double offset) const;
  /// Whether the session states the patient's head and front (--head,
  /// --front) for a scan whose file gives no orientation: the CT view stands
  /// as they say.
  bool patientStated() const;
  /// The view in a window set by hand, while the view is dragged (the
  /// session takes it when the button is let go).
  void previewScanWindow(double width, double level);
  /// Shows (or hides) the scan as the session asks; a line that cannot be
  /// shown gets a message.
  void showScan();
  /// After a change of the view alone (its plane's offset, its window): the
  /// view and the status, without rebuilding the scene.
  void refreshScan();
  /// The message as the scene's rebuild left it, before the view's line:
  /// refreshScan starts from it.
  std::string sceneMessage;
  /// The view's square in the 3D view (scanPlaneSheet, scanPlaneOutline).
  void showScanPlane();
  /// Its colour, unlit: a pale blue.
  static constexpr std::array<double, 3> kScanPlaneColour{ 0.6, 0.75, 0.95 };
  /// "CT on cut line 1's plane": what the view shows, for the status line and the report.
  std::string scanShown() const;
  std::string scanShownKey, scanWhy; ///< what the view shows (cut key and line), why it shows nothing
  /// What the view shows, and the segment's move its cyan section is drawn
  /// for (piece and matrix).
  lkapp::ScanPicture scanPicture;
  std::string scanMovedKey, scanMeasuredKey;
  /// The measurements whose points lie on the picture's plane (within
  /// kOnScanPlane mm), as picked, into its `measured` and `measuredValues`;
  /// `picking`: with the points of one under way.
  void measuredOnPlane(lkapp::ScanPicture& picture, bool picking) const;
  static constexpr double kOnScanPlane = 1.0;
  /// Whether all the points lie within kOnScanPlane of the frame's plane: a
  /// measurement drawn on the view (and removed there with Delete).
  static bool onScanPlane(const std::vector<std::array<double, 3>>& points, const lkapp::ViewFrame& frame);
  /// The moved segment's section by the frame's plane where `matrix` puts
  /// it; none when no segment is moved.
  std::vector<std::vector<std::array<double, 3>>> movedSection(
    const lkapp::ViewFrame& frame, const std::array<double, 16>& matrix) const;
  /// How far beside a plane a piece's section is taken (mm): a cut along a
  /// drawn line leaves a cap flat only to a few hundredths of a millimetre,
  /// and the view's plane can lie in it (the segment moved a whole number of
  /// mm along its cut's normal, the view wheeled as far).
  static constexpr double kBesideACap = 0.05;
  /// Draws the view, with the moved segment's section where `matrix` puts
  /// it, when the picture (showScan) or the move changed: placeSegment calls
  /// it, during a drag too.
  void showScanMoved(const std::array<double, 16>& matrix);
  /// Where the view's picture lies on the bone: its square, a faint sheet
  /// and its outline in the 3D view (it follows the wheel's moves).
  vtkNew<vtkActor> scanPlaneSheet, scanPlaneOutline;
  /// While the view is shown, the main view's camera draws the bone in the
  /// rest of the window (its user transform, after the projection).
  vtkNew<vtkTransform> roomForScan;
  /// The export's pictures of the scan, two per closed cut line, on its
  /// plane and across it (cut_line1_ct.png, cut_line1_across_ct.png, ...),
  /// and, with the view's plane moved off its cut's (the session's
  /// scanOffset), the view as shown (`shown`, cut_line1_ct_+3mm.png, and its
  /// title): their names; false with `error` when one could not be made or
  /// written (the others are).
  bool writeScanPictures(const std::string& folder, std::vector<std::string>& written, std::string& shown,
    std::string& shownTitle, std::string& error);
  /// cut_line1_ct.png, cut_line1_across_ct.png; off the cut's plane by
  /// `offset` mm toward the viewer, cut_line1_ct_+3mm.png.
  static std::string scanPictureName(int number, bool across, double offset);

  /// Call before a change: the session as it was goes on the undo stack.
  void remember() { remember(session); }
  /// After a drag that changed the session live: the session before it.
  void remember(const Session& before);

  /// A segment is a piece of a cut: without one (the cut off or failed, one
  /// piece) the session's segment waits, and the whole bone is not moved.
  bool hasSegment() const
  {
    return pieces.size() >= 2 && session.segment >= 0 && session.segment < static_cast<int>(pieces.size());
  }
  /// The piece the segment's transform moves; -1 when there is none.
  int movedPiece() const { return hasSegment() ? session.segment : -1; }

  /// Where piece p of the cut lies: its point farthest from every other
  /// piece (on its surface, before deformations and the segment's move).
  std::array<double, 3> anchorOf(std::size_t p) const;

  /// The distance from each point to each piece's surface (VTK_DOUBLE_MAX
  /// for an empty piece), one cell locator per piece.
  std::vector<std::vector<double>> pieceDistances(const std::vector<std::array<double, 3>>& points) const;

  /// How near a point measured on the CT must lie to a piece's surface to go
  /// with it, in mm, when the bone's outline on the view's plane does not
  /// enclose it.
  static constexpr double kBesideTheBone = 3.0;
  /// The piece a point of the CT view's plane goes with: the nearest, when
  /// the point lies within kBesideTheBone of its surface or inside the bone's
  /// outline on that plane (the cortex, the marrow, the canal, a root); -1
  /// for the soft tissue, which the plan does not move. `nearest` gets the
  /// distance to the nearest piece.
  int pieceOnScan(const std::array<double, 3>& point, double& nearest) const;

  /// After a cut made anew (computeCut), as the pieces can be numbered anew
  /// when a line is added or taken away: the segment becomes the piece
  /// nearest its anchor (nothing without an anchor, an older session, or
  /// without a cut), and each deformation the piece whose surface is nearest
  /// its centre (a point picked on the piece it was made on); each keeps its
  /// own piece when that is as near (a point on a cut line lies on both).
  /// The notice says what moved; a deformation out of reach of its piece
  /// gets a message.
  void followPieces();

  vtkSmartPointer<vtkMatrix4x4> segmentMatrix() const;

  /// Shows the segment where its transform puts it.
  void placeSegment(const std::array<double, 16>& matrix);

  /// The segment's transform as the surgery plan states it: which piece, the
  /// matrix, its translation and rotation angle.
  std::string segmentText() const;

  void setup();
  /// Turns the corner cube as the view turns (before every render).
  void followCamera();

  /// A drawn stroke into the session. A loop around a bone is never seen
  /// whole from one side, so a stroke can be drawn in parts, the view turned
  /// between them: points that start within joinTolerance of an end of the
  /// last stroke's line, while that line is open (and not paint) and the mode
  /// is the same, continue that stroke (appended at its end, or put reversed
  /// before its start) instead of starting a new one; the stroke closes when
  /// its ends meet. Returns true when they continued it.
  bool addStroke(const std::vector<std::array<double, 3>>& points);

  /// A saw line: the osteotomy plane (origin, normal) seen edge-on, and a
  /// point on the bone under the line. The plane's section of the bone
  /// nearest that point becomes a closed split-mode stroke (every point of
  /// the section: sawStep), so the cut is flat and its
  /// cap too. Returns false, with the reason, when the plane meets the bone
  /// there in no closed loop.
  bool addSawStroke(const std::array<double, 3>& origin, const std::array<double, 3>& normal,
    const std::array<double, 3>& onBone, std::string& why);

  /// The plane's section of the bone as a stroke (sawStep): the loop with the
  /// point nearest `near`, whose distance goes to `gap`. Empty without a loop.
  std::vector<std::array<double, 3>> sectionStroke(const std::array<double, 3>& origin,
    const std::array<double, 3>& normal, const std::array<double, 3>& near, double& gap) const;

  /// A saw line's points on this bone: its plane's section, the loop through
  /// (or nearest) its first point, traced as addSawStroke does. Without a
  /// loop, its stored points, and `why` says so.
  std::vector<std::array<double, 3>> sawPoints(const Stroke& st, std::string& why) const;

  /// The spacing of a saw line's points: none, every point of the section
  /// (where the plane crosses a mesh edge) is kept. Consecutive points then
  /// share a face, and the split follows the plane exactly. With fewer (one
  /// every half join radius, or only those a hundredth of it apart) the
  /// split's walk between points turned back, or found no face ahead, where
  /// the plane passes close to vertices (a capped piece's rim).
  static constexpr double sawStep() { return 0.0; }

  /// The ends of the last stroke while its line is open and can be continued
  /// (empty otherwise): shown as markers of joinTolerance's radius.
  std::vector<std::array<double, 3>> openEnds() const;

  /// The strokes and the cut, kept while they do not change (the lattice,
  /// Metro, segment and deformation keys do not redo them).
  struct CutStage
  {
    std::string key;
    std::vector<std::pair<vtkSmartPointer<vtkPolyData>, double>> lines; ///< feature lines, shade
    std::vector<std::size_t> lineStrokes; ///< the stroke each line came from (a failed stroke has none)
    /// Whether stroke i made no line (its message says why): it is drawn
    /// where it was drawn, for Delete to find it there.
    bool madeNoLine(std::size_t i) const
    {
      return std::find(lineStrokes.begin(), lineStrokes.end(), i) == lineStrokes.end();
    }
    /// The cut's pieces (vtkLKExtractCutPieceFilter), each with cell data
    /// "Cap" only (a deformation drag carries what a piece has, every frame).
    std::vector<vtkSmartPointer<vtkPolyData>> pieces;
    /// Each piece's feature edges (its point ids, smaller first): where the
    /// cut went through it, and the strokes' lines on it. Its lattice keeps
    /// them exactly.
    std::vector<std::vector<std::array<vtkIdType, 2>>> featureEdges;
    /// The bone with the strokes' lines split in, and the closed lines the
    /// cut took (MeshPointId into it): exported, so that the CLI tools can
    /// cut again (latticekit-cut) or fit with the lines kept.
    vtkSmartPointer<vtkPolyData> surface, loops;
    std::string message;
    bool failed = false;
    int innerWallLines = 0; ///< lines the cut added on a hollow bone's inner walls
    bool lastLineOpen = false; ///< the last stroke gave an open line (not paint), which a drag can continue
  } cut;
  /// What the strokes gave, one after another: each stroke's line is made on
  /// the surface the strokes before it left (a split stroke splits faces), so
  /// stroke i's result depends on strokes 0 to i. Kept between rebuilds, a
  /// stroke drawn, continued or undone redoes only the strokes from it on,
  /// and the cut switched on or off none (on a whole skull of 1.5 million
  /// faces each stroke costs seconds).
  struct StrokeStep
  {
    std::string key; ///< strokeKey of the stroke
    /// The surface after it; released (null) for all but the last few
    /// steps, whose surfaces a rebuild starts from.
    vtkSmartPointer<vtkPolyData> surface;
    std::vector<std::pair<vtkSmartPointer<vtkPolyData>, double>> lines; ///< every line so far, as it lies on surface
    std::vector<std::size_t> lineStrokes; ///< the stroke each line came from
    std::string message; ///< the strokes' messages so far
  };
  std::vector<StrokeStep> strokeSteps;
  vtkPolyData* strokeStepsBone = nullptr; ///< the bone they were made on (with its MTime)
  vtkMTimeType strokeStepsBoneTime = 0;
  /// How many strokes' lines the cut stage made, and took from strokeSteps, in all.
  std::size_t strokesMade = 0, strokesReused = 0;
  /// One deformation filter per piece: it keeps the refined mesh between
  /// updates, so a drag or a brush dab costs one deformation.
  std::vector<vtkSmartPointer<vtkLKPatchDeformationFilter>> deformers;

  void computeCut();

  /// The filter call for one deformation.
  static void addTo(vtkLKPatchDeformationFilter* f, const Deformation& d);

  /// The deformation filter of piece p (made on first use).
  vtkLKPatchDeformationFilter* deformer(std::size_t p);

  /// The session's deformations applied to the cut pieces, in order.
  void applyDeformations();

  /// The piece each of the session's names names (-1: none, without
  /// pieces), found again when the cut or the names change (the nearest
  /// piece to its point); a name on two pieces gets a message.
  std::vector<int> nameTargets;
  /// The cut (CutStage::key) and the names' points nameTargets was found for.
  std::string namesCutKey;
  std::vector<std::array<double, 3>> namesAt;
  void resolveNames();
  /// The session's name of piece p (the last one on it), or -1.
  int nameIndex(std::size_t p) const;
  /// Piece p's name, or empty.
  std::string pieceName(std::size_t p) const;
  /// Each named piece's name in the view, at the point it was named at
  /// (moved with the segment).
  struct NameCaption
  {
    int piece = -1;
    std::array<double, 3> at{ 0, 0, 0 };
    vtkSmartPointer<vtkCaptionActor2D> actor;
  };
  std::vector<NameCaption> nameCaptions;
  void showNames();
  /// Before each render: where each name and measured value stands beside
  /// its point, in the window and not over another (lkapp::placeLabels).
  void placeCaptions();
  /// "piece 1 'distal segment'", or "piece 1" without a name.
  std::string pieceLabel(std::size_t p) const;
  /// Names piece p (at: the point picked on it) or, with an empty name,
  /// takes its name away; the earlier names on it go. False, with `why`,
  /// for a name validPieceName refuses, another piece has, or an unnamed
  /// piece goes by in the structure set ("piece 2").
  bool namePiece(std::size_t p, const std::array<double, 3>& at, const std::string& name, std::string& why);
  /// Naming in the window (t): 1 while a click picks the piece, 2 while its
  /// name is typed (Return keeps it, Escape drops it).
  int naming = 0;
  int namingPiece = -1;
  std::array<double, 3> namingAt{ 0, 0, 0 };
  std::string namingText;
  /// Dead accents and the Compose key while a name is typed: "´" then "e"
  /// types "é".
  lkapp::KeyComposer composer;

  /// Moving the segment by numbers (v): the text typed so far, while
  /// `typingMove`.
  bool typingMove = false;
  std::string moveText;
  /// The lattice's vertices per piece typed (L), while `typingLattice`.
  bool typingLattice = false;
  std::string latticeText;
  /// Where the patient's axes point, for the prompt ("x to the left, y
  /// back, z up" in LPS), empty when the bone's coordinate system is not
  /// known.
  std::string axesText;
  /// The segment's move as a surgeon states it: how far its centre moves
  /// (mm) and its turns (degrees) about the x, y and z axes through its
  /// centre, applied in that order.
  struct SegmentMove
  {
    std::array<double, 3> translation{ 0, 0, 0 }, angles{ 0, 0, 0 };
  };
  /// The segment's centre: the middle of its bounds, before its move and
  /// deformations.
  std::array<double, 3> segmentCentre() const;
  /// The session's segment matrix as a SegmentMove, and back.
  SegmentMove segmentMove() const;
  static std::array<double, 16> moveMatrix(const std::array<double, 3>& centre, const SegmentMove& move);
  /// Reads "x y z" or "x y z rx ry rz" (spaces or commas between; mm and
  /// degrees) and puts the segment there: the move replaces the segment's
  /// move so far (undo brings that back). False, with `why`, for other text,
  /// a translation beyond 1000 mm or a turn beyond 360 degrees.
  bool moveSegmentTo(const std::string& text, std::string& why);

  /// Measuring in the window: u, a distance (two clicks on the bone); a, an
  /// angle (three: an arm's end, the vertex, the other arm's end).
  /// `measuring` is the clicks a measurement takes (0: not measuring);
  /// `measurePicked` holds the points clicked so far (in their pieces'
  /// frames) and `measurePickedPieces` their pieces.
  int measuring = 0;
  /// The three clicks set the mirror plane (O), not an angle.
  bool settingPlane = false;
  std::vector<std::array<double, 3>> measurePicked;
  std::vector<int> measurePickedPieces;
  /// The measurements in the view, with the segment where `shownMatrix`
  /// puts it (during a drag too): a distance's line, its ends and its
  /// length at its middle; an angle's two arms and its degrees at its
  /// vertex; the points clicked while one is being measured.
  std::vector<vtkSmartPointer<vtkCaptionActor2D>> measureCaptions;
  vtkNew<vtkActor> measureMarker;
  vtkSmartPointer<vtkActor> measureActor;
  void showMeasurements();
  /// The measurement drawn nearest the display point (x, y), its line or
  /// its arms within `pixels`: in the bone's view, or, where (x, y) lies on
  /// the CT view, one drawn there (on its plane, as picked); -1 for none.
  /// `distance` gets how many pixels away it is.
  int measurementAt(int x, int y, double pixels, double& distance) const;
  /// The stroke whose line on the bone is drawn nearest the display point
  /// (x, y) of the bone's view, within `pixels` (a stroke that made no line:
  /// where it was drawn); -1 for none (and on the CT view). `distance` as
  /// above.
  int strokeAt(int x, int y, double pixels, double& distance) const;
  /// The deformation of `piece` whose region holds `point` (in the piece's
  /// own frame, picked on the surface its deformations left): the latest
  /// such, as it lies on top; -1 for none. A bump's region is its ball and
  /// a box's its cube, each swept along its normal by its amount (what it
  /// raised stands that far out; a bump's falls off, so a point beside it
  /// can be within its reach); a smoothing dab's is its ball.
  int deformationAt(int piece, const std::array<double, 3>& point) const;
  /// The deformations that go with deformation i when it is removed
  /// (Delete), first and last: itself, or for a smoothing dab the brush
  /// stroke it belongs to: the run of dabs on its piece around it with its
  /// stroke number; in a session without the numbers, each within its radius
  /// of the one before (a stroke places one every third of a radius; two
  /// strokes one after the other, the second from where the first ended,
  /// are then one).
  std::pair<std::size_t, std::size_t> deformationGroup(std::size_t i) const;
  /// Removes deformation i with its group (deformationGroup); the notice
  /// says what went ("deformation 1 (box on piece 0) removed (z: back)").
  void removeDeformation(std::size_t i);
  /// Whether (x, y) lies on the CT view, drawn.
  bool onScanView(int x, int y) const { return scanRenderer->GetDraw() && scanRenderer->IsInViewport(x, y); }
  /// (x, y)'s distance in pixels from the segment a-b drawn by `view` (its
  /// world coordinates; the camera's room for the CT view included).
  static double pixelsFrom(
    vtkRenderer* view, int x, int y, const std::array<double, 3>& a, const std::array<double, 3>& b);
  /// The segment's transform as the view shows it (placeSegment's).
  std::array<double, 16> shownMatrix{ 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  /// Where a point of piece `piece` (in its own frame) is shown: moved by
  /// `matrix` on the moved segment, else where it is.
  std::array<double, 3> shownPoint(const std::array<double, 3>& point, int piece,
    const std::array<double, 16>& matrix) const;
  /// A measurement's points (from, to; at for an angle) where `matrix`
  /// shows them.
  Measurement placed(const Measurement& m, const std::array<double, 16>& matrix) const;
  /// A measurement's value as its points stand: "23.41 mm" for a distance,
  /// "112.5 deg" for an angle.
  static std::string valueText(const Measurement& m);
  /// Its value as the plan places it (the segment moved).
  std::string measuredText(const Measurement& m) const { return valueText(placed(m, session.segmentMatrix)); }
  /// A measurement's text: "23.41 mm", "112.5 deg".
  static std::string lengthText(double length);
  static std::string degreesText(double degrees);

  /// Re-runs the plan from the bone: strokes, cut (kept while unchanged),
  /// deformations, lattices, colours.
  void rebuild();

  /// Piece p's lattice (600 vertices or the session's, at least twice its
  /// lines' vertices, at most half the piece's) and its smooth surface, with
  /// the piece's feature edges (its cut lines, the strokes' lines) kept
  /// exactly: fitted again only when the piece's points or faces, the count
  /// or those edges changed since the last fit.
  FittedLattice& latticeOf(std::size_t p);

  /// A 64-bit digest of a mesh's points and polygons, a count and edges: FNV-1a
  /// over 8-byte words, each scrambled first (splitmix64's finaliser, so that
  /// every bit of a word reaches every bit of the digest); the skull's 40 MB
  /// in a few milliseconds.
  static std::uint64_t geometryKey(vtkPolyData* pd, vtkIdType count, const std::vector<std::array<vtkIdType, 2>>& edges);

  /// The surface without its line cells (the feature lines a stroke left on it).
  static vtkSmartPointer<vtkPolyData> facesOnly(vtkPolyData* surface);

  /// An actor for a surface, shaded with its normals (vtkPolyDataNormals).
  /// Its mapper is the one the last rebuild showed the same data with, if
  /// any: the normals and the triangles already on the graphics card are
  /// kept (a second and more on a whole skull), and a surface changed in
  /// place (a deformation's drag) updates them, as the pipeline does.
  vtkSmartPointer<vtkActor> addActorData(vtkPolyData* pd, std::array<double, 3> colour, bool scalars);

  vtkSmartPointer<vtkActor> addActor(vtkAlgorithmOutput* port, vtkPolyData*, std::array<double, 3> colour, bool scalars);

  /// An actor of `mapper` in `colour`, in the scene.
  vtkSmartPointer<vtkActor> addActorOf(vtkPolyDataMapper* mapper, std::array<double, 3> colour);

  /// addActorData's mappers, by the data shown and whether its scalars
  /// colour it (the data held, so that its address is not another's): this
  /// rebuild's, and the last one's while this one is made.
  struct ShownMapper
  {
    vtkSmartPointer<vtkPolyData> data;
    vtkSmartPointer<vtkPolyDataMapper> mapper;
  };
  std::map<std::pair<vtkPolyData*, bool>, ShownMapper> shownMappers, lastShownMappers;

  /// A line on the bone (not picked) in `colour`, `width` pixels wide.
  vtkSmartPointer<vtkActor> addLineActor(vtkPolyData* line, const std::array<double, 3>& colour, double width);

  /// cutSummary's text for the current cut and pieces.
  std::string summaryOfCut();
  /// Piece p's facts (closed, volume), kept while the piece is the same
  /// object, unmodified: a rebuild that leaves the piece (a Metro or lattice
  /// toggle, a deformation of another piece) measures nothing again (the
  /// skull's 560,000 faces take 0.1-0.2 s).
  const lkapp::PieceFacts& factsOf(std::size_t p);
  struct KeptFacts
  {
    vtkPolyData* piece = nullptr;
    vtkMTimeType time = 0;
    lkapp::PieceFacts facts;
  };
  std::vector<KeptFacts> pieceFacts;

  void updateStatus();
  /// The CT view between the status lines and the messages (square, at the
  /// left): smaller where they would reach under it; redrawn when it changes.
  void placeScanView();
  /// The band of the window between the status lines and the messages: its
  /// bottom 6 pixels above the status's top, its top 6 below the messages.
  std::array<double, 2> betweenTheTexts() const;

  void showStroke();

  /// The plan as the batch report and the export give it: the strokes, each
  /// piece (closed, volume, deformation), each cut line's length, centre and
  /// plane with the distances and angles between them, the deformations, the
  /// segment's move, and the messages. No timings.
  std::string planText();
  /// Compares the input a replayed session names (file, bone bounds) with
  /// this one's, sets inputWarnings when they differ, and records this input
  /// in the session (saved and exported with it).
  void checkReplayedInput(bool replayed);

  /// Prints planText(), then what the run cost (deformation frames, lattice
  /// fits reused).
  void report();

  /// Writes every piece (STL, VTP, OBJ; the segment where the plan moved it),
  /// the surface the cut was made on (surface.vtp), the lines it took
  /// (cut_lines.vtp), the plan (plan.txt, planText()), the window's picture
  /// of it (plan.png), the session that replays it (session.json) and, with
  /// a moved segment, its transform
  /// (segment_transform.txt), and, when the bone came from a DICOM CT
  /// (referenceImage), the closed pieces as the ROIs of an RT structure set
  /// on the CT's slices (pieces.dcm, "piece 0", ...), for the hospital's
  /// PACS or planning system. Files of these names that an earlier export
  /// left and this plan does not make (more pieces, say) are removed.
  bool exportPieces(const std::string& folder, std::string& error);
  /// The export's RT structure set (pieces.dcm) of the `exported` pieces (as
  /// written: the segment where the plan moves it), when the bone came from
  /// a DICOM CT; sets exportNote and exportedStructureSet. The writer's
  /// errors when it could not be written, else empty.
  std::string exportStructureSet(const std::string& folder, const std::vector<vtkSmartPointer<vtkPolyData>>& exported);

  /// The window's picture as a PNG file (whole or not at all). False with `error`.
  bool screenshot(const std::string& path, std::string& error);
};

} // namespace lkplanner
