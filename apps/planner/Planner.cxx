#include "planner/Planner.h"

#include "common/AppSupport.h"
#include "common/AtomicFile.h"
#include "common/CutReport.h"
#include "common/DistanceColourBar.h"
#include "common/JsonFields.h"
#include "common/PlaneSection.h"
#include "common/TextFont.h"

#include "vtkLKClosedLineCutFilter.h"
#include "vtkLKExtractCutPieceFilter.h"
#include "vtkLKLatticeFitFilter.h"
#include "vtkLKLatticeSurfaceFilter.h"
#include "vtkLKMedicalImageReader.h"
#include "vtkLKMetroFilter.h"
#include "vtkLKPatchDeformationFilter.h"
#include "vtkLKPolyDataConversion.h"
#include "vtkLKStructureSetWriter.h"
#include "vtkLKSymmetryPlaneFilter.h"

#include "latticekit/ClosestPointTree.h"
#include "vtkLKStrokeFeatureLineFilter.h"
#include "vtkLKText.h"

#include <vtkActor.h>
#include <vtkAppendPolyData.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCaptionActor2D.h>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkExtractEdges.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkInteractorObserver.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataMapper2D.h>
#include <vtkProperty2D.h>
#include <vtkPolyDataNormals.h>
#include <vtkSphereSource.h>
#include <vtkStaticCellLocator.h>
#include <vtkStaticPointLocator.h>
#include <vtkMath.h>
#include <vtkProperty.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtkMatrix4x4.h>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <regex>
#include <tuple>
#include <cstring>
#include <functional>
#include <map>
#include <set>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

namespace lkplanner
{
namespace
{
bool isIdentity(const std::array<double, 16>& m)
{
  for (int i = 0; i < 16; ++i)
    if (m[static_cast<std::size_t>(i)] != (i % 5 == 0 ? 1.0 : 0.0))
      return false;
  return true;
}

std::string matrixText(const std::array<double, 16>& m)
{
  std::ostringstream os;
  os.precision(6);
  os << std::fixed;
  for (int r = 0; r < 4; ++r)
  {
    os << "  ";
    for (int c = 0; c < 4; ++c)
      os << (c ? " " : "") << m[static_cast<std::size_t>(4 * r + c)];
    os << "\n";
  }
  return os.str();
}

/// `text` with every line broken at spaces to at most `width` characters
/// (a longer word stays whole).
std::string wrapped(const std::string& text, std::size_t width)
{
  // Widths count characters, not UTF-8 bytes (a Cyrillic letter takes two).
  const auto length = [](const std::string& t) {
    return static_cast<std::size_t>(
      std::count_if(t.begin(), t.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
  };
  std::string out;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
  {
    std::string current;
    std::istringstream words(line);
    for (std::string word; words >> word;)
    {
      if (!current.empty() && length(current) + 1 + length(word) > width)
      {
        out += current + "\n";
        current = "  "; // continuation lines are indented
      }
      current += (current.empty() || current == "  " ? "" : " ") + word;
    }
    out += current + "\n";
  }
  if (!out.empty())
    out.pop_back();
  return out;
}

/// Appends `line` to a message of several lines.
void addLine(std::string& message, const std::string& line)
{
  message += (message.empty() ? "" : "\n") + line;
}

/// Each line of `text` as its own line of `message`, after `prefix`.
void addLines(std::string& message, const std::string& prefix, const std::string& text)
{
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
    if (!line.empty())
      addLine(message, prefix + line);
}
} // namespace

const char* const kHelp = "d: draw on/off (right drag turns the view; drag on from an orange end) | 1 paint 2 nearest 3 snap 4 split | p: saw line | c: CT at a cut (C: its window)\n"
                    "x: cut (capped) | l: lattice, L: size | m: Metro colours | n: pick the segment (smallest first) | g: move it (shift: rotate) | v: by numbers | r: reset\n"
                    "f: deform (bump, box, smooth; drag up/down) | [ ]: tool radius | u: distance, a: angle | Delete: what is pointed at | o: mirror image, O: its plane\n"
                    "t: name a piece (click it, type, Return) | z: undo  y: redo | w: save session | e: export pieces | q: quit | mouse: rotate, pan, zoom";

const char* toolName(int tool)
{
  return tool == BUMP ? "bump" : tool == BOX ? "box" : tool == SMOOTH ? "smooth" : "off";
}

/// A marker ball (an open line's end, a measurement's first point).
vtkSmartPointer<vtkPolyData> ballAt(const std::array<double, 3>& centre, double radius)
{
  vtkNew<vtkSphereSource> ball;
  ball->SetCenter(centre.data());
  ball->SetRadius(radius);
  ball->SetThetaResolution(16);
  ball->SetPhiResolution(12);
  ball->Update();
  return ball->GetOutput();
}

/// A caption in the view: `text` with a leader to its attachment point,
/// `offset` pixels from it, bold in `colour` on a light background (readable
/// over the Metro colours), not pickable.
vtkSmartPointer<vtkCaptionActor2D> captionActor(
  const std::string& text, const std::array<double, 3>& colour, int fontSize, const std::array<int, 2>& offset)
{
  auto caption = vtkSmartPointer<vtkCaptionActor2D>::New();
  caption->SetCaption(text.c_str());
  caption->BorderOff();
  caption->LeaderOn();
  caption->ThreeDimensionalLeaderOff();
  caption->GetTextActor()->SetTextScaleModeToNone();
  vtkTextProperty* property = caption->GetCaptionTextProperty();
  property->SetFontSize(fontSize);
  property->SetColor(colour.data());
  property->BoldOn();
  property->ItalicOff();
  property->ShadowOff();
  property->SetJustificationToLeft();
  property->SetBackgroundColor(1.0, 1.0, 1.0);
  property->SetBackgroundOpacity(0.75);
  caption->GetProperty()->SetColor(colour.data()); // the leader
  // A name in a script VTK's compiled font lacks (Greek, Cyrillic, kanji)
  // is drawn with an installed font that has it; one that no font has is
  // said once.
  if (const std::string lacking = lkapp::useFontFor(property, text); !lacking.empty())
  {
    static std::set<std::string> said;
    if (said.insert(text).second)
      std::fprintf(stderr, "planner: no installed font draws '%s' of '%s'; the view leaves them out\n",
        lkvtk::shownText(lacking, 64).c_str(), lkvtk::shownText(text, 64).c_str());
  }
  caption->SetPosition(offset[0], offset[1]);
  std::vector<char32_t> characters;
  lkvtk::decodeUTF8(text, &characters);
  caption->SetWidth(0.01 * static_cast<double>(characters.size() + 2));
  caption->SetHeight(0.0027 * fontSize);
  caption->PickableOff();
  return caption;
}

namespace
{
/// The corners of the plane (origin, unit normal) over a box: two axes in
/// it (the one nearest z first, so a mid-sagittal plane stands upright),
/// the box's corners projected onto them, and 5 % more on each side.
vtkSmartPointer<vtkPoints> planeCorners(
  const std::array<double, 3>& origin, const std::array<double, 3>& normal, const double bounds[6])
{
  std::array<double, 3> u =
    std::abs(normal[2]) < 0.9 ? std::array<double, 3>{ 0, 0, 1 } : std::array<double, 3>{ 0, 1, 0 };
  const double along = vtkMath::Dot(u.data(), normal.data());
  for (int k = 0; k < 3; ++k)
    u[k] -= along * normal[k];
  vtkMath::Normalize(u.data());
  std::array<double, 3> v;
  vtkMath::Cross(normal.data(), u.data(), v.data());
  double low[2] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX }, high[2] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (int corner = 0; corner < 8; ++corner)
  {
    const double x[3] = { bounds[corner & 1] - origin[0], bounds[2 + ((corner >> 1) & 1)] - origin[1],
      bounds[4 + ((corner >> 2) & 1)] - origin[2] };
    const double a[2] = { vtkMath::Dot(x, u.data()), vtkMath::Dot(x, v.data()) };
    for (int k = 0; k < 2; ++k)
    {
      low[k] = std::min(low[k], a[k]);
      high[k] = std::max(high[k], a[k]);
    }
  }
  const double margin[2] = { 0.05 * (high[0] - low[0]), 0.05 * (high[1] - low[1]) };
  auto corners = vtkSmartPointer<vtkPoints>::New();
  for (const auto& [cu, cv] : { std::make_pair(0, 0), std::make_pair(1, 0), std::make_pair(1, 1), std::make_pair(0, 1) })
  {
    const double a = cu ? high[0] + margin[0] : low[0] - margin[0];
    const double b = cv ? high[1] + margin[1] : low[1] - margin[1];
    corners->InsertNextPoint(
      origin[0] + a * u[0] + b * v[0], origin[1] + a * u[1] + b * v[1], origin[2] + a * u[2] + b * v[2]);
  }
  return corners;
}

/// A plane's square drawn by two actors: a faint sheet and its outline,
/// through its four corners in order around it.
void showSquare(vtkPoints* corners, vtkActor* sheetActor, vtkActor* outlineActor)
{
  const vtkIdType quad[4] = { 0, 1, 2, 3 }, loop[5] = { 0, 1, 2, 3, 0 };
  vtkNew<vtkPolyData> sheet, outline;
  sheet->SetPoints(corners);
  sheet->Allocate(1);
  sheet->InsertNextCell(VTK_QUAD, 4, quad);
  outline->SetPoints(corners);
  outline->Allocate(1);
  outline->InsertNextCell(VTK_POLY_LINE, 5, loop);
  vtkPolyDataMapper::SafeDownCast(sheetActor->GetMapper())->SetInputData(sheet);
  vtkPolyDataMapper::SafeDownCast(outlineActor->GetMapper())->SetInputData(outline);
}
} // namespace

std::array<double, 3> pieceColour(std::size_t p)
{
  const double colours[4][3] = { { 0.93, 0.85, 0.65 }, { 0.6, 0.75, 0.93 }, { 0.7, 0.9, 0.7 }, { 0.95, 0.7, 0.7 } };
  return { colours[p % 4][0], colours[p % 4][1], colours[p % 4][2] };
}

void Planner::remember(const Session& before)
{
  undoStack.push_back(before);
  redoStack.clear();
}

vtkSmartPointer<vtkMatrix4x4> Planner::segmentMatrix() const
{
  auto m = vtkSmartPointer<vtkMatrix4x4>::New();
  m->DeepCopy(session.segmentMatrix.data());
  return m;
}

void Planner::placeSegment(const std::array<double, 16>& matrix)
{
  for (const NameCaption& c : nameCaptions)
    c.actor->SetAttachmentPoint(shownPoint(c.at, c.piece, matrix).data());
  for (std::size_t p = 0; p < pieceActors.size(); ++p)
    for (auto& a : pieceActors[p])
    {
      if (static_cast<int>(p) == movedPiece())
      {
        vtkNew<vtkMatrix4x4> m;
        m->DeepCopy(matrix.data());
        a->SetUserMatrix(m);
      }
      else
        a->SetUserMatrix(nullptr);
    }
  shownMatrix = matrix;
  showMeasurements(); // an end on the segment moves with it
  updateContacts(matrix);
  updateMirrorFit(matrix);
  showScanMoved(matrix);
}

const Planner::MirrorImage& Planner::mirrorImage()
{
  if (mirror.made && mirror.madeWith == session.mirrorPlane)
    return mirror;
  mirror = MirrorImage();
  mirror.made = true;
  mirror.madeWith = session.mirrorPlane;
  mirrorFitPiece = nullptr; // the segment's distance before its move, anew
  vtkNew<vtkLKSymmetryPlaneFilter> symmetry;
  symmetry->SetInputData(facesOnly(bone));
  // The patient's left-right axis: x in LPS and RAS alike (a CT's patient
  // lies along z, facing y).
  symmetry->SetInitialNormal(1.0, 0.0, 0.0);
  if (!session.mirrorPlane.empty())
  {
    // The plane the surgeon set through three points (checked when read or
    // clicked).
    std::array<double, 3> origin, normal;
    std::string why;
    if (!lkplanner::planeThrough(session.mirrorPlane, origin, normal, why))
    {
      mirror.error = why;
      return mirror;
    }
    symmetry->FitPlaneOff();
    symmetry->SetGivenPlaneOrigin(origin.data());
    symmetry->SetGivenPlaneNormal(normal.data());
  }
  const int before = lkapp::errorCount();
  symmetry->Update();
  if (symmetry->GetOutput()->GetNumberOfPolys() == 0)
  {
    mirror.error = lkapp::errorCount() > before ? lkapp::errorsSince(before) : std::string("no mirror image was made");
    return mirror;
  }
  mirror.surface = vtkSmartPointer<vtkPolyData>::New();
  mirror.surface->ShallowCopy(symmetry->GetOutput());
  symmetry->GetPlaneOrigin(mirror.origin.data());
  symmetry->GetPlaneNormal(mirror.normal.data());
  for (auto* values : { &mirror.origin, &mirror.normal })
    for (double& v : *values)
      v = std::abs(v) < 1e-9 ? 0.0 : v; // rounding's dust (a plane set by clicks), and no "-0.0000"
  mirror.mean = symmetry->GetMeanDistance();
  mirror.largest = symmetry->GetMaximumDistance();
  mirror.kept = symmetry->GetKeptFraction();
  lk::TriangleMesh triangles;
  mirror.error = lkvtk::toTriangleMesh(mirror.surface, triangles);
  try
  {
    if (mirror.error.empty())
      mirror.tree = std::make_shared<const lk::ClosestPointTree>(triangles);
  }
  catch (const std::exception& e)
  {
    mirror.error = e.what();
  }
  if (!mirror.tree)
  {
    mirror.surface = nullptr;
    return mirror;
  }
  vtkPolyDataMapper::SafeDownCast(mirrorActor->GetMapper())->SetInputData(mirror.surface);
  // The plane over the bone's extent: a faint sheet and its outline.
  double bounds[6];
  bone->GetBounds(bounds);
  showSquare(planeCorners(mirror.origin, mirror.normal, bounds), mirrorPlaneActor, mirrorPlaneOutline);
  return mirror;
}

Planner::MirrorFit Planner::mirrorFitOf(const std::array<double, 16>& matrix) const
{
  MirrorFit fit;
  if (!mirror.tree || !hasSegment())
    return fit;
  vtkPolyData* segment = pieces[static_cast<std::size_t>(session.segment)];
  double sum = 0.0;
  lk::ClosestPointTree::Hit hit; // each vertex's hit starts its neighbour's search
  for (std::size_t k = 0; k < mirrorFitVertices.size(); ++k)
  {
    std::array<double, 3> x;
    segment->GetPoint(mirrorFitVertices[k], x.data());
    x = lkapp::placedPoint(matrix, x);
    const lk::Vec3 q(x[0], x[1], x[2]);
    hit = k == 0 ? mirror.tree->closest(q) : mirror.tree->closest(q, hit);
    sum += hit.distance;
    fit.largest = std::max(fit.largest, hit.distance);
  }
  fit.valid = !mirrorFitVertices.empty();
  fit.mean = fit.valid ? sum / static_cast<double>(mirrorFitVertices.size()) : 0.0;
  return fit;
}

void Planner::updateMirrorFit(const std::array<double, 16>& matrix)
{
  segmentToMirror = MirrorFit();
  if (!session.mirror || !mirror.surface || !hasSegment())
    return;
  vtkPolyData* segment = pieces[static_cast<std::size_t>(session.segment)];
  if (segment != mirrorFitPiece || segment->GetMTime() != mirrorFitTime)
  {
    // A piece the drag has not seen: its vertices of the bone's own surface
    // (a cap's lie inside the mirror image, where the cut went through the
    // bone), and its fit where it was cut.
    std::vector<char> onBone(static_cast<std::size_t>(segment->GetNumberOfPoints()), 0);
    vtkDataArray* cap = segment->GetCellData()->GetArray("Cap");
    vtkNew<vtkIdList> ids;
    for (vtkIdType c = 0; c < segment->GetNumberOfCells(); ++c)
    {
      const int type = segment->GetCellType(c);
      if ((type != VTK_TRIANGLE && type != VTK_POLYGON && type != VTK_QUAD) || (cap && cap->GetTuple1(c) != 0.0))
        continue;
      segment->GetCellPoints(c, ids);
      for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
        onBone[static_cast<std::size_t>(ids->GetId(k))] = 1;
    }
    mirrorFitVertices.clear();
    for (vtkIdType i = 0; i < segment->GetNumberOfPoints(); ++i)
      if (onBone[static_cast<std::size_t>(i)])
        mirrorFitVertices.push_back(i);
    mirrorFitPiece = segment;
    mirrorFitTime = segment->GetMTime();
    segmentToMirrorBefore = mirrorFitOf(Session().segmentMatrix);
  }
  segmentToMirror = isIdentity(matrix) ? segmentToMirrorBefore : mirrorFitOf(matrix);
}

double Planner::degreesFromX(const std::array<double, 3>& normal)
{
  const double x[3] = { 1.0, 0.0, 0.0 };
  return vtkMath::DegreesFromRadians(vtkMath::AngleBetweenVectors(normal.data(), x));
}

std::string Planner::mirrorText() const
{
  if (!session.mirror)
    return "";
  if (!mirror.surface)
    return "mirror image: none (" + mirror.error + ")\n";
  const double tilt = degreesFromX(mirror.normal);
  char line[600];
  if (mirror.madeWith.empty())
    std::snprintf(line, sizeof line,
      "mirror image: across the bone's plane of symmetry through (%.2f, %.2f, %.2f), normal (%.4f, %.4f, %.4f), "
      "%.1f deg from x; the bone is %.2f mm from it on average, %.2f mm at most; the plane was fitted to %.0f %% of "
      "the bone (the rest lies farther from its mirror)\n",
      mirror.origin[0], mirror.origin[1], mirror.origin[2], mirror.normal[0], mirror.normal[1], mirror.normal[2],
      tilt, mirror.mean, mirror.largest, 100.0 * mirror.kept);
  else
  {
    const auto& p = mirror.madeWith;
    std::snprintf(line, sizeof line,
      "mirror image: across the plane set through (%.2f, %.2f, %.2f), (%.2f, %.2f, %.2f) and (%.2f, %.2f, %.2f), "
      "normal (%.4f, %.4f, %.4f), %.1f deg from x; the bone is %.2f mm from it on average, %.2f mm at most\n",
      p[0][0], p[0][1], p[0][2], p[1][0], p[1][1], p[1][2], p[2][0], p[2][1], p[2][2], mirror.normal[0],
      mirror.normal[1], mirror.normal[2], tilt, mirror.mean, mirror.largest);
  }
  std::string text = line;
  if (segmentToMirror.valid)
  {
    std::snprintf(line, sizeof line,
      "segment and the mirror image: %.2f mm apart on average, %.2f mm at most (%.2f and %.2f before the segment's "
      "move)\n",
      segmentToMirror.mean, segmentToMirror.largest, segmentToMirrorBefore.mean, segmentToMirrorBefore.largest);
    text += line;
  }
  return text;
}

void Planner::updateContacts(const std::array<double, 16>& matrix)
{
  contacts.clear();
  overlapMarker->SetVisibility(false);
  if (!hasSegment() || isIdentity(matrix))
    return;
  std::vector<vtkPolyData*> shown;
  for (const auto& piece : pieces)
    shown.push_back(piece);
  if (shown != contactPieces)
  {
    contactSurfaces.clear();
    for (vtkPolyData* piece : shown)
      contactSurfaces.push_back(std::make_unique<lkapp::ContactSurface>(piece));
    contactPieces = shown;
  }
  // Closer than this the pieces touch (a cut's two caps lie on each other).
  const double touch = 1e-4 * bone->GetLength();
  const auto s = static_cast<std::size_t>(session.segment);
  vtkNew<vtkPoints> inside;
  for (std::size_t p = 0; p < pieces.size(); ++p)
    if (p != s)
      contacts.emplace_back(
        static_cast<int>(p), lkapp::contactOf(*contactSurfaces[s], matrix, *contactSurfaces[p], touch, inside));
  if (inside->GetNumberOfPoints() > 0)
  {
    vtkNew<vtkPolyData> points;
    points->SetPoints(inside);
    vtkNew<vtkCellArray> verts;
    for (vtkIdType i = 0; i < inside->GetNumberOfPoints(); ++i)
      verts->InsertNextCell(1, &i);
    points->SetVerts(verts);
    vtkPolyDataMapper::SafeDownCast(overlapMarker->GetMapper())->SetInputData(points);
    overlapMarker->SetVisibility(true);
  }
}

std::string Planner::contactStatus() const
{
  const std::pair<int, lkapp::Contact>* shown = nullptr;
  for (const auto& c : contacts)
  {
    const bool deeper = c.second.overlap && (!shown || !shown->second.overlap || c.second.depth > shown->second.depth);
    const bool nearer = !c.second.overlap && (!shown || (!shown->second.overlap && c.second.gap < shown->second.gap));
    if (deeper || nearer)
      shown = &c;
  }
  if (!shown)
    return "";
  char text[120];
  if (shown->second.overlap)
    std::snprintf(text, sizeof text, "OVERLAPS piece %d by %.2f mm", shown->first, shown->second.depth);
  else
    std::snprintf(text, sizeof text, "%.2f mm from piece %d", shown->second.gap, shown->first);
  return text;
}

std::array<double, 3> Planner::shownPoint(const std::array<double, 3>& point, int piece,
  const std::array<double, 16>& matrix) const
{
  return piece < 0 || piece != movedPiece() ? point : lkapp::placedPoint(matrix, point);
}

Measurement Planner::placed(const Measurement& m, const std::array<double, 16>& matrix) const
{
  Measurement shown = m;
  shown.from = shownPoint(m.from, m.pieces[Measurement::FROM], matrix);
  shown.to = shownPoint(m.to, m.pieces[Measurement::TO], matrix);
  shown.at = shownPoint(m.at, m.pieces[Measurement::AT], matrix);
  return shown;
}

std::string Planner::valueText(const Measurement& m)
{
  return m.angle ? degreesText(m.degrees()) : lengthText(m.length());
}

std::string Planner::degreesText(double degrees)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.1f deg", degrees);
  return text;
}

std::string Planner::segmentText() const
{
  if (!hasSegment())
    return "";
  // The move as a surgeon states it (and types it with v): how far the
  // segment's centre goes, and its turn about the axes through the centre.
  // The matrix's own translation is the move of the coordinates' origin,
  // far from the bone, once the segment turns.
  const auto& m = session.segmentMatrix;
  const double trace = m[0] + m[5] + m[10];
  const double angle = std::acos(std::clamp((trace - 1.0) / 2.0, -1.0, 1.0)) * 180.0 / vtkMath::Pi();
  const std::array<double, 3> c = segmentCentre();
  const SegmentMove move = segmentMove();
  char line[400];
  std::snprintf(line, sizeof line, "segment: %s moved, translation %.2f %.2f %.2f mm (of its centre), rotation %.2f deg\n",
    pieceLabel(static_cast<std::size_t>(session.segment)).c_str(), move.translation[0], move.translation[1],
    move.translation[2], angle);
  std::string text = line;
  // How it meets the bone beside it where the plan puts it.
  for (const auto& [piece, contact] : contacts)
    text += "segment and " + pieceLabel(static_cast<std::size_t>(piece)) + ": " + lkapp::contactText(contact) + "\n";
  std::snprintf(line, sizeof line,
    "segment centre: (%.2f, %.2f, %.2f); the rotation is %.2f %.2f %.2f deg about x, y, z through it, in that order%s%s\n",
    c[0], c[1], c[2], move.angles[0], move.angles[1], move.angles[2], axesText.empty() ? "" : " (",
    axesText.empty() ? "" : (axesText + ")").c_str());
  return text + line + matrixText(m);
}

std::array<double, 3> Planner::segmentCentre() const
{
  std::array<double, 3> centre{ 0, 0, 0 };
  if (!hasSegment() || static_cast<std::size_t>(session.segment) >= cut.pieces.size())
    return centre;
  double b[6];
  cut.pieces[static_cast<std::size_t>(session.segment)]->GetBounds(b);
  return { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
}

Planner::SegmentMove Planner::segmentMove() const
{
  const auto& m = session.segmentMatrix;
  SegmentMove move;
  const std::array<double, 3> c = segmentCentre();
  const std::array<double, 3> moved = lkapp::placedPoint(m, c);
  for (std::size_t i = 0; i < 3; ++i)
    move.translation[i] = moved[i] - c[i];
  // R = Rz(c) Ry(b) Rx(a): m[8] = -sin b, m[9] = cos b sin a,
  // m[10] = cos b cos a, m[4] = cos b sin c, m[0] = cos b cos c.
  const double degrees = 180.0 / vtkMath::Pi();
  const double b = std::asin(std::clamp(-m[8], -1.0, 1.0));
  if (std::abs(m[8]) < 1.0 - 1e-12)
  {
    move.angles = { std::atan2(m[9], m[10]) * degrees, b * degrees, std::atan2(m[4], m[0]) * degrees };
  }
  else
    move.angles = { 0.0, b * degrees, std::atan2(-m[1], m[5]) * degrees }; // a and c turn about one axis
  for (auto* values : { &move.translation, &move.angles })
    for (double& v : *values)
      v = std::abs(v) < 1e-9 ? 0.0 : v; // rounding's dust, and no "-0.00"
  return move;
}

std::array<double, 16> Planner::moveMatrix(const std::array<double, 3>& centre, const SegmentMove& move)
{
  vtkNew<vtkTransform> t;
  t->PostMultiply(); // each step after the last, about the fixed axes
  t->Translate(-centre[0], -centre[1], -centre[2]);
  t->RotateX(move.angles[0]);
  t->RotateY(move.angles[1]);
  t->RotateZ(move.angles[2]);
  t->Translate(centre[0] + move.translation[0], centre[1] + move.translation[1], centre[2] + move.translation[2]);
  std::array<double, 16> m{};
  for (int r = 0; r < 4; ++r)
    for (int k = 0; k < 4; ++k)
      m[static_cast<std::size_t>(4 * r + k)] = t->GetMatrix()->GetElement(r, k);
  return m;
}

bool Planner::moveSegmentTo(const std::string& text, std::string& why)
{
  std::string spaced = text;
  std::replace(spaced.begin(), spaced.end(), ',', ' ');
  std::istringstream in(spaced);
  std::vector<double> values;
  for (std::string word; in >> word;)
  {
    char* end = nullptr;
    const double v = std::strtod(word.c_str(), &end);
    if (end != word.c_str() + word.size() || !std::isfinite(v))
    {
      why = "'" + word + "' is not a number: type x y z (mm), then rx ry rz (degrees) to turn it";
      return false;
    }
    values.push_back(v);
  }
  if (values.size() != 3 && values.size() != 6)
  {
    why = "type three numbers, x y z (mm), or six, x y z rx ry rz (mm, then degrees about x, y, z): " +
      std::to_string(values.size()) + " given";
    return false;
  }
  SegmentMove move;
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    const double most = i < 3 ? 1000.0 : 360.0;
    if (std::abs(values[i]) > most)
    {
      why = i < 3 ? "a move beyond 1000 mm is a slip" : "a turn beyond 360 degrees is a slip";
      return false;
    }
    (i < 3 ? move.translation[i] : move.angles[i - 3]) = values[i];
  }
  remember();
  session.segmentMatrix = moveMatrix(segmentCentre(), move);
  placeSegment(session.segmentMatrix);
  return true;
}

void Planner::setup()
{
  window->AddRenderer(renderer);
  overlay->SetLayer(1);
  overlay->InteractiveOff();
  overlay->SetActiveCamera(renderer->GetActiveCamera());
  window->SetNumberOfLayers(2);
  window->AddRenderer(overlay);
  // The scan on a cut line's plane: the lower left, above the status lines,
  // over the measurements' layer, opaque (a layer above the first keeps the
  // picture beneath it unless told otherwise).
  scanRenderer->SetLayer(1);
  scanRenderer->PreserveColorBufferOff();
  scanRenderer->PreserveDepthBufferOff();
  scanRenderer->SetViewport(0.005, 0.24, 0.375, 0.735);
  scanRenderer->InteractiveOff();
  scanRenderer->DrawOff();
  window->AddRenderer(scanRenderer);
  // While it is shown, the bone is drawn smaller, right of it (after the
  // projection: picks and drags go through the same transform).
  roomForScan->Translate(0.37, 0.0, 0.0);
  roomForScan->Scale(0.62, 0.62, 1.0);
  window->SetSize(1000, 750);
  window->SetWindowName("latticekit planner");
  renderer->SetBackground(1, 1, 1);
  help->SetInput(kHelp);
  help->GetTextProperty()->SetFontSize(13);
  help->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
  help->SetDisplayPosition(8, 8);
  renderer->AddViewProp(help);
  status->GetTextProperty()->SetFontSize(15);
  status->GetTextProperty()->SetColor(0.1, 0.1, 0.4);
  status->SetDisplayPosition(8, 78);
  renderer->AddViewProp(status);
  // Problems and warnings, at the top where they are seen while drawing.
  messages->GetTextProperty()->SetFontSize(14);
  messages->GetTextProperty()->SetColor(0.6, 0.1, 0.0);
  messages->GetTextProperty()->SetVerticalJustificationToTop();
  messages->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  messages->GetPositionCoordinate()->SetValue(0.01, 0.985);
  renderer->AddViewProp(messages);
  scalarBar->SetVisibility(false);
  // At the right, between the orientation cube and the status lines (its
  // default place reaches down over them).
  scalarBar->SetPosition(0.82, 0.22);
  scalarBar->SetPosition2(0.17, 0.66);
  renderer->AddViewProp(scalarBar);
  vtkNew<vtkPolyDataMapper> sm;
  sm->SetInputData(strokePd);
  strokeActor->SetMapper(sm);
  strokeActor->GetProperty()->SetColor(0.9, 0.1, 0.1);
  strokeActor->GetProperty()->SetLineWidth(3);
  strokeActor->GetProperty()->SetPointSize(6);
  strokeActor->PickableOff(); // strokes are picked on the bone, never on themselves
  renderer->AddActor(strokeActor);
  vtkNew<vtkPolyDataMapper2D> sawMapper;
  sawMapper->SetInputData(sawPd);
  sawActor->SetMapper(sawMapper);
  sawActor->GetProperty()->SetColor(0.85, 0.1, 0.1);
  sawActor->GetProperty()->SetLineWidth(2);
  sawActor->SetVisibility(false);
  renderer->AddViewProp(sawActor);
  preview->SetVisibility(false);
  preview->PickableOff();
  renderer->AddActor(preview);
  // The first point of a distance being measured (u).
  vtkNew<vtkPolyDataMapper> markerMapper;
  measureMarker->SetMapper(markerMapper);
  measureMarker->GetProperty()->SetColor(0.55, 0.0, 0.45);
  measureMarker->SetVisibility(false);
  measureMarker->PickableOff();
  overlay->AddActor(measureMarker);
  vtkNew<vtkPolyDataMapper> overlapMapper;
  overlapMarker->SetMapper(overlapMapper);
  overlapMarker->GetProperty()->SetColor(0.9, 0.05, 0.05);
  overlapMarker->GetProperty()->SetPointSize(5);
  overlapMarker->GetProperty()->RenderPointsAsSpheresOn();
  overlapMarker->SetVisibility(false);
  overlapMarker->PickableOff();
  overlay->AddActor(overlapMarker);
  // The mirror image: translucent over the bone, so that the bone shows
  // through where the two agree and the mirror stands out where they do not.
  vtkNew<vtkPolyDataMapper> mirrorMapper;
  mirrorMapper->ScalarVisibilityOff();
  mirrorActor->SetMapper(mirrorMapper);
  mirrorActor->GetProperty()->SetColor(0.55, 0.35, 0.85);
  mirrorActor->GetProperty()->SetOpacity(0.35);
  mirrorActor->SetVisibility(false);
  mirrorActor->PickableOff(); // strokes and picks land on the bone
  renderer->AddActor(mirrorActor);
  for (vtkActor* actor : { mirrorPlaneActor.Get(), mirrorPlaneOutline.Get() })
  {
    vtkNew<vtkPolyDataMapper> mapper;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(0.45, 0.25, 0.75);
    actor->GetProperty()->LightingOff();
    actor->SetVisibility(false);
    actor->PickableOff();
    renderer->AddActor(actor);
  }
  mirrorPlaneActor->GetProperty()->SetOpacity(0.12);
  mirrorPlaneOutline->GetProperty()->SetLineWidth(2.0);
  for (vtkActor* actor : { scanPlaneSheet.Get(), scanPlaneOutline.Get() })
  {
    vtkNew<vtkPolyDataMapper> mapper;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(kScanPlaneColour[0], kScanPlaneColour[1], kScanPlaneColour[2]);
    actor->GetProperty()->LightingOff();
    actor->SetVisibility(false);
    actor->PickableOff(); // strokes and picks land on the bone
    renderer->AddActor(actor);
  }
  scanPlaneSheet->GetProperty()->SetOpacity(0.15);
  scanPlaneOutline->GetProperty()->SetLineWidth(2.0);
  // The patient's sides, as medical viewers show them: a mandible is nearly
  // symmetric, and a cut planned on the wrong side is the error to prevent.
  // Patient x, y, z point to the left, back and up in LPS; to the right,
  // front and up in RAS. Without a known system the cube would guess.
  if (const std::string space = lkapp::coordinateSpace(bone); !space.empty())
  {
    const bool lps = space == "LPS";
    axesText = lps ? "x to the left, y back, z up" : "x to the right, y to the front, z up";
    marker->SetXPlusFaceText(lps ? "L" : "R");
    marker->SetXMinusFaceText(lps ? "R" : "L");
    marker->SetYPlusFaceText(lps ? "P" : "A");
    marker->SetYMinusFaceText(lps ? "A" : "P");
    marker->SetZPlusFaceText("S");
    marker->SetZMinusFaceText("I");
    // The S face reads upright seen from above with the front up (the cube
    // turns with the view; VTK's default text on that face is a quarter turn
    // off).
    marker->SetZFaceTextRotation(lps ? 90.0 : -90.0);
    marker->SetFaceTextScale(0.6);
    marker->GetCubeProperty()->SetColor(0.92, 0.92, 0.95);
    marker->GetTextEdgesProperty()->SetColor(0.5, 0.5, 0.6);
    for (vtkProperty* face : { marker->GetXPlusFaceProperty(), marker->GetXMinusFaceProperty(),
           marker->GetYPlusFaceProperty(), marker->GetYMinusFaceProperty(), marker->GetZPlusFaceProperty(),
           marker->GetZMinusFaceProperty() })
      face->SetColor(0.1, 0.1, 0.4);
    marker->PickableOff();
    // Seen face-on the cube shows one letter; arrows to the patient's left,
    // back and top (the axes' positive ends) say which way the others lie.
    markerAxes->SetTotalLength(1.3, 1.3, 1.3);
    markerAxes->SetShaftTypeToCylinder();
    markerAxes->SetCylinderRadius(0.03);
    markerAxes->SetXAxisLabelText(lps ? "L" : "R");
    markerAxes->SetYAxisLabelText(lps ? "P" : "A");
    markerAxes->SetZAxisLabelText("S");
    for (vtkCaptionActor2D* label : { markerAxes->GetXAxisCaptionActor2D(), markerAxes->GetYAxisCaptionActor2D(),
           markerAxes->GetZAxisCaptionActor2D() })
    {
      label->GetCaptionTextProperty()->SetFontSize(12);
      label->GetCaptionTextProperty()->SetColor(0.1, 0.1, 0.4);
      label->GetCaptionTextProperty()->ShadowOff();
      label->GetCaptionTextProperty()->ItalicOff();
    }
    markerAxes->PickableOff();
    markerRenderer->AddViewProp(markerAxes);
    markerRenderer->AddViewProp(marker);
    markerRenderer->SetViewport(0.87, 0.85, 0.995, 0.995); // top right, above the distance colour bar
    markerRenderer->SetLayer(1);
    markerRenderer->InteractiveOff();
    window->AddRenderer(markerRenderer);
    renderer->AddObserver(vtkCommand::StartEvent, this, &Planner::followCamera);
  }
  radius = 0.05 * bone->GetLength();
  // The stroke filter's "ends meet" is also how near a drag continues a line.
  if (const double tolerance = vtkLKStrokeFeatureLineFilter::DefaultCloseTolerance(bone); tolerance > 0.0)
    joinTolerance = tolerance;
}

void Planner::followCamera()
{
  vtkCamera* view = renderer->GetActiveCamera();
  vtkCamera* cube = markerRenderer->GetActiveCamera();
  double d[3];
  view->GetDirectionOfProjection(d);
  cube->SetFocalPoint(0.0, 0.0, 0.0);
  cube->SetPosition(-5.0 * d[0], -5.0 * d[1], -5.0 * d[2]);
  cube->SetViewUp(view->GetViewUp());
  cube->SetParallelProjection(false);
  markerRenderer->ResetCamera(-1.0, 1.0, -1.0, 1.0, -1.0, 1.0); // the cube, its arrows and room for their letters
}

namespace
{
double distance(const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  return std::sqrt(vtkMath::Distance2BetweenPoints(a.data(), b.data()));
}
} // namespace

std::vector<std::array<double, 3>> Planner::openEnds() const
{
  if (!cut.lastLineOpen || session.strokes.empty() || session.strokes.back().points.size() < 2)
    return {};
  const auto& points = session.strokes.back().points;
  return { points.front(), points.back() };
}

bool Planner::addSawStroke(const std::array<double, 3>& origin, const std::array<double, 3>& normal,
  const std::array<double, 3>& onBone, std::string& why)
{
  // The point under the line lies on the plane and on the bone, so on the
  // section: a loop farther away is another part of the bone.
  double gap = 0.0;
  Stroke saw;
  saw.points = sectionStroke(origin, normal, onBone, gap);
  if (saw.points.empty() || gap > joinTolerance)
  {
    why = "the saw line's plane meets the bone there in no closed loop (at an open border of the surface?)";
    return false;
  }
  saw.mode = vtkLKStrokeFeatureLineFilter::SPLIT;
  saw.saw = true;
  saw.sawOrigin = origin;
  saw.sawNormal = normal;
  session.strokes.push_back(saw);
  return true;
}

std::vector<std::array<double, 3>> Planner::sectionStroke(const std::array<double, 3>& origin,
  const std::array<double, 3>& normal, const std::array<double, 3>& near, double& gap) const
{
  const auto loops = lkapp::planeSectionLoops(bone, origin, normal);
  const int nearest = lkapp::nearestLoop(loops, near, &gap);
  if (nearest < 0)
    return {};
  return lkapp::strokeAlongLoop(loops[static_cast<std::size_t>(nearest)], sawStep(), 0.0);
}

std::vector<std::array<double, 3>> Planner::sawPoints(const Stroke& st, std::string& why) const
{
  double gap = 0.0;
  std::vector<std::array<double, 3>> points =
    sectionStroke(st.sawOrigin, st.sawNormal, st.points.empty() ? st.sawOrigin : st.points.front(), gap);
  if (points.empty())
  {
    why = "its plane meets this bone in no closed loop; the line as it was drawn is used";
    return st.points;
  }
  return points;
}

bool Planner::addStroke(const std::vector<std::array<double, 3>>& points)
{
  const std::vector<std::array<double, 3>> ends = openEnds();
  if (!points.empty() && !ends.empty() && session.strokes.back().mode == mode)
  {
    auto& last = session.strokes.back().points;
    if (distance(points.front(), ends[1]) <= joinTolerance)
    {
      last.insert(last.end(), points.begin(), points.end());
      return true;
    }
    if (distance(points.front(), ends[0]) <= joinTolerance)
    {
      last.insert(last.begin(), points.rbegin(), points.rend());
      return true;
    }
  }
  session.strokes.push_back({ mode, points });
  return false;
}

namespace
{
/// The first two closed lines that share a point of the surface, as a
/// sentence; empty when they are all apart.
std::string closedLinesMeeting(const std::vector<vtkSmartPointer<vtkPolyData>>& lines,
  const std::vector<std::string>& names, vtkPolyData* surface)
{
  std::map<vtkIdType, std::size_t> owner; // mesh point -> the first line through it
  for (std::size_t l = 0; l < lines.size(); ++l)
  {
    vtkDataArray* ids = lines[l]->GetPointData()->GetArray("MeshPointId");
    std::set<vtkIdType> own;
    for (vtkIdType i = 0; ids && i < ids->GetNumberOfTuples(); ++i)
      own.insert(static_cast<vtkIdType>(ids->GetComponent(i, 0)));
    for (vtkIdType v : own)
    {
      const auto [it, added] = owner.emplace(v, l);
      if (added || v < 0 || v >= surface->GetNumberOfPoints())
        continue;
      double p[3];
      surface->GetPoint(v, p);
      char place[80];
      std::snprintf(place, sizeof(place), "(%.1f, %.1f, %.1f)", p[0], p[1], p[2]);
      return names[it->second] + " and " + names[l] + " meet on the bone at " + place +
        ": each cut needs a closed line apart from the others (two cuts that meet, as a closed wedge's, are "
        "not supported); undo one (z) or draw it apart";
    }
  }
  return {};
}

using FeatureEdges = std::vector<std::array<vtkIdType, 2>>;

/// The edges of `piece`'s faces (smaller id first), sorted.
FeatureEdges faceEdgesOf(vtkPolyData* piece)
{
  FeatureEdges edges;
  auto it = vtk::TakeSmartPointer(piece->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    for (vtkIdType k = 0; k < n; ++k)
      edges.push_back({ std::min(ids[k], ids[(k + 1) % n]), std::max(ids[k], ids[(k + 1) % n]) });
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

/// `edges` of a cut piece on `deformed`, that piece after the patch
/// deformation, which keeps the cut piece's `kept` points first, in order,
/// and splits edges at new points (its adaptive refinement): an edge still
/// there stays; a split one becomes its parts, through the new point joined
/// to both ends that lies nearest the straight path, as often as it was
/// split. `lost` counts the edges for which no such path was found.
FeatureEdges onDeformed(const FeatureEdges& edges, vtkPolyData* deformed, vtkIdType kept, std::size_t& lost)
{
  const FeatureEdges all = faceEdgesOf(deformed);
  std::vector<std::vector<vtkIdType>> around(static_cast<std::size_t>(deformed->GetNumberOfPoints()));
  for (const auto& e : all)
  {
    around[static_cast<std::size_t>(e[0])].push_back(e[1]);
    around[static_cast<std::size_t>(e[1])].push_back(e[0]);
  }
  auto has = [&](vtkIdType a, vtkIdType b) {
    return std::binary_search(all.begin(), all.end(), std::array<vtkIdType, 2>{ std::min(a, b), std::max(a, b) });
  };
  auto length = [&](vtkIdType a, vtkIdType b) {
    double x[3], y[3];
    deformed->GetPoint(a, x);
    deformed->GetPoint(b, y);
    return std::sqrt(vtkMath::Distance2BetweenPoints(x, y));
  };
  std::set<std::array<vtkIdType, 2>> out;
  std::function<bool(vtkIdType, vtkIdType, int)> path = [&](vtkIdType a, vtkIdType b, int depth) {
    if (has(a, b))
    {
      out.insert({ std::min(a, b), std::max(a, b) });
      return true;
    }
    vtkIdType middle = -1;
    double shortest = VTK_DOUBLE_MAX;
    for (const vtkIdType m : around[static_cast<std::size_t>(a)])
      if (m >= kept && has(m, b) && length(a, m) + length(m, b) < shortest)
      {
        middle = m;
        shortest = length(a, m) + length(m, b);
      }
    return depth > 0 && middle >= 0 && path(a, middle, depth - 1) && path(middle, b, depth - 1);
  };
  lost = 0;
  for (const auto& e : edges)
    if (e[1] >= deformed->GetNumberOfPoints() || !path(e[0], e[1], 16))
      ++lost;
  return FeatureEdges(out.begin(), out.end());
}

/// The feature edges of `piece` (its point ids, smaller first): the edges of
/// its cut lines (MeshPointId naming its points; may be null) and of the
/// strokes' `lines` (MeshPointId naming the points of `surface`, the one the
/// cut was made on, which the piece's point data "InputPointId" maps; without
/// it the piece is that surface) that are edges of its faces.
FeatureEdges featureEdgesOf(vtkPolyData* piece, vtkPolyData* cutLines,
  const std::vector<std::pair<vtkSmartPointer<vtkPolyData>, double>>& lines, vtkPolyData* surface)
{
  const FeatureEdges faceEdges = faceEdgesOf(piece);
  std::set<std::array<vtkIdType, 2>> kept;
  auto add = [&](vtkIdType a, vtkIdType b) {
    const std::array<vtkIdType, 2> e{ std::min(a, b), std::max(a, b) };
    if (e[0] >= 0 && e[0] != e[1] && std::binary_search(faceEdges.begin(), faceEdges.end(), e))
      kept.insert(e);
  };
  std::vector<lk::EdgeKey> edges;
  if (cutLines)
    lkvtk::lineEdges(cutLines, piece, edges);
  for (const auto& [a, b] : edges)
    add(a, b);
  vtkDataArray* input = piece->GetPointData()->GetArray("InputPointId");
  std::map<vtkIdType, vtkIdType> toPiece;
  for (vtkIdType i = 0; input && i < input->GetNumberOfTuples(); ++i)
    toPiece.emplace(static_cast<vtkIdType>(input->GetTuple1(i)), i);
  auto inPiece = [&](vtkIdType v) -> vtkIdType {
    const auto found = toPiece.find(v);
    return !input ? v : found != toPiece.end() ? found->second : -1;
  };
  for (const auto& line : lines)
  {
    edges.clear();
    lkvtk::lineEdges(line.first, surface, edges);
    for (const auto& [a, b] : edges)
      add(inPiece(a), inPiece(b));
  }
  return FeatureEdges(kept.begin(), kept.end());
}

/// A piece as the planner keeps it: its cells and points, its field data and
/// the cell data "Cap" alone.
vtkSmartPointer<vtkPolyData> withCapOnly(vtkPolyData* piece)
{
  auto kept = vtkSmartPointer<vtkPolyData>::New();
  kept->ShallowCopy(piece);
  kept->GetPointData()->Initialize();
  kept->GetCellData()->Initialize();
  if (vtkDataArray* cap = piece->GetCellData()->GetArray("Cap"))
    kept->GetCellData()->AddArray(cap);
  return kept;
}
} // namespace

void Planner::computeCut()
{
  const std::string key = cutKey(session);
  if (!cut.pieces.empty() && cut.key == key)
    return;
  cut = CutStage();
  cut.key = key;
  deformers.clear();
  vtkSmartPointer<vtkPolyData> surface = bone;
  std::vector<vtkSmartPointer<vtkPolyData>> closedLines;
  std::vector<std::string> closedNames; // "stroke 3 (saw line)", one per closed line
  for (std::size_t i = 0; i < session.strokes.size(); ++i)
  {
    cut.lastLineOpen = false;
    const Stroke& st = session.strokes[i];
    const std::string which = "stroke " + std::to_string(i + 1) + " (" + (st.saw ? "saw line" : modeName(st.mode)) + ")";
    // A saw line follows its plane's section of this bone (the same points
    // as when it was drawn on the same bone).
    std::string sawWhy;
    const std::vector<std::array<double, 3>> points = st.saw ? sawPoints(st, sawWhy) : st.points;
    if (!sawWhy.empty())
      addLine(cut.message, which + ": " + sawWhy);
    vtkNew<vtkPoints> pts;
    for (const auto& p : points)
      pts->InsertNextPoint(p.data());
    vtkNew<vtkPolyData> stroke;
    stroke->SetPoints(pts);
    vtkNew<vtkLKStrokeFeatureLineFilter> f;
    f->SetInputData(facesOnly(surface));
    f->SetStrokeData(stroke);
    f->SetMode(st.mode);
    const int errorsBefore = lkapp::errorCount(), warningsBefore = lkapp::warningCount();
    f->Update();
    const std::string warned = lkapp::warningsSince(warningsBefore);
    if (!warned.empty())
      addLines(cut.message, which + ": ", warned);
    if (lkapp::errorCount() > errorsBefore || f->GetOutput()->GetNumberOfPoints() == 0)
    {
      const std::string why = lkapp::errorsSince(errorsBefore);
      addLine(cut.message, which + " failed: " + (why.empty() ? "no feature line" : why));
      continue; // the stroke stays in the session; the message says why
    }
    auto next = vtkSmartPointer<vtkPolyData>::New();
    next->ShallowCopy(f->GetOutput());
    surface = next;
    // The earlier lines onto the new surface: a split stroke that crosses
    // one cuts its edges (the cut needs its loops along the mesh's edges).
    for (auto& earlier : cut.lines)
    {
      vtkNew<vtkPolyData> carried;
      if (f->CarryLine(earlier.first, carried))
        earlier.first->DeepCopy(carried);
    }
    auto line = vtkSmartPointer<vtkPolyData>::New();
    line->DeepCopy(f->GetFeatureLineOutput());
    cut.lines.emplace_back(line, st.mode == vtkLKStrokeFeatureLineFilter::PAINT ? 0.2 : 0.0);
    cut.lineStrokes.push_back(i);
    const bool closed = line->GetFieldData()->GetArray("Closed")->GetComponent(0, 0) > 0.5;
    if (st.mode != vtkLKStrokeFeatureLineFilter::PAINT)
    {
      if (closed)
      {
        closedLines.push_back(line);
        closedNames.push_back(which);
      }
      cut.lastLineOpen = !closed;
    }
  }
  vtkSmartPointer<vtkPolyData> faces = facesOnly(surface);
  cut.surface = faces;
  // Closed lines that meet: the cut needs them apart, and the surgeon needs to
  // know which two strokes and where (the cut filter can name only a mesh
  // point).
  std::string meeting;
  if (session.cut)
    meeting = closedLinesMeeting(closedLines, closedNames, faces);
  if (!meeting.empty())
  {
    addLine(cut.message, "the cut failed: " + meeting);
    cut.failed = true;
  }
  else if (session.cut && !closedLines.empty())
  {
    vtkNew<vtkPolyData> loops;
    vtkNew<vtkPoints> lp;
    vtkNew<vtkCellArray> lc;
    vtkNew<vtkIdTypeArray> ids;
    ids->SetName("MeshPointId");
    for (const auto& l : closedLines)
    {
      vtkDataArray* mid = l->GetPointData()->GetArray("MeshPointId");
      lc->InsertNextCell(l->GetNumberOfPoints());
      for (vtkIdType i = 0; i < l->GetNumberOfPoints(); ++i)
      {
        lc->InsertCellPoint(lp->InsertNextPoint(l->GetPoint(i)));
        ids->InsertNextValue(static_cast<vtkIdType>(mid->GetComponent(i, 0)));
      }
    }
    loops->SetPoints(lp);
    loops->SetLines(lc);
    loops->GetPointData()->AddArray(ids);
    vtkNew<vtkLKClosedLineCutFilter> cutter;
    cutter->SetInputData(faces);
    cutter->SetLinesData(loops);
    cutter->SetCapping(session.capping);
    const int before = lkapp::errorCount(), warningsBefore = lkapp::warningCount();
    cutter->Update();
    const std::string warned = lkapp::warningsSince(warningsBefore);
    if (!warned.empty())
      addLines(cut.message, "the cut: ", warned);
    if (lkapp::errorCount() == before)
    {
      cut.loops = loops;
      vtkNew<vtkLKExtractCutPieceFilter> extract;
      extract->SetInputConnection(cutter->GetOutputPort());
      for (int r = 0; r < cutter->GetNumberOfPieces(); ++r)
      {
        extract->SetPiece(r);
        extract->Update();
        cut.featureEdges.push_back(
          featureEdgesOf(extract->GetOutput(), extract->GetCutLinesOutput(), cut.lines, faces));
        cut.pieces.push_back(withCapOnly(extract->GetOutput()));
      }
      cut.innerWallLines = cutter->GetNumberOfInnerWallLines();
    }
    else
    {
      addLine(cut.message, "the cut failed: " + lkapp::errorsSince(before));
      cut.failed = true;
    }
  }
  else if (session.cut)
    addLine(cut.message, "no closed line to cut along: draw a stroke whose ends meet");
  if (cut.pieces.empty())
  {
    auto whole = vtkSmartPointer<vtkPolyData>::New();
    whole->ShallowCopy(faces);
    cut.featureEdges.assign(1, featureEdgesOf(whole, nullptr, cut.lines, faces));
    cut.pieces.push_back(whole);
  }
  followPieces(); // the pieces may be numbered anew
}

void Planner::addTo(vtkLKPatchDeformationFilter* f, const Deformation& d)
{
  const auto& c = d.centre;
  const double r = d.radius;
  if (d.tool == "bump")
    f->AddFunctionalDeformation(c[0], c[1], c[2], d.amount, d.falloff, r);
  else if (d.tool == "box")
    f->AddRangeDeformation(c[0] - r, c[0] + r, c[1] - r, c[1] + r, c[2] - r, c[2] + r, d.amount * d.normal[0],
      d.amount * d.normal[1], d.amount * d.normal[2]);
  else
    f->AddSmoothingDeformation(c[0], c[1], c[2], r, d.iterations);
}

vtkLKPatchDeformationFilter* Planner::deformer(std::size_t p)
{
  deformers.resize(cut.pieces.size());
  if (!deformers[p])
  {
    deformers[p] = vtkSmartPointer<vtkLKPatchDeformationFilter>::New();
    deformers[p]->SetInputData(cut.pieces[p]);
  }
  return deformers[p];
}

void Planner::applyDeformations()
{
  pieces = cut.pieces;
  std::vector<std::vector<const Deformation*>> perPiece(pieces.size());
  for (std::size_t i = 0; i < session.deformations.size(); ++i)
  {
    const Deformation& d = session.deformations[i];
    if (d.piece < static_cast<int>(pieces.size()))
      perPiece[static_cast<std::size_t>(d.piece)].push_back(&d);
    else
      addLine(message, "deformation " + std::to_string(i) + " is on piece " + std::to_string(d.piece) +
        ", which does not exist: the plan has " + std::to_string(pieces.size()) + " piece(s)");
  }
  for (std::size_t p = 0; p < pieces.size(); ++p)
  {
    if (perPiece[p].empty())
    {
      if (p < deformers.size() && deformers[p])
        deformers[p]->RemoveAllDeformations(); // undone: the next drag starts from the cut piece
      continue;
    }
    vtkLKPatchDeformationFilter* f = deformer(p);
    f->RemoveAllDeformations();
    for (const Deformation* d : perPiece[p])
      addTo(f, *d);
    f->CheckCrossingsOn(); // a drag turns it off
    const int before = lkapp::errorCount();
    f->Update(); // only what changed is redone (the filter keeps its state)
    if (lkapp::errorCount() > before)
    {
      addLine(message, "cannot deform piece " + std::to_string(p) + ": " + lkapp::errorsSince(before));
      continue;
    }
    if (const vtkIdType crossings = static_cast<vtkIdType>(lkapp::fieldValue(f->GetOutput(), "SelfCrossings")))
    {
      const vtkIdType before = static_cast<vtkIdType>(lkapp::fieldValue(f->GetOutput(), "SelfCrossingsBefore"));
      if (before > 0)
        addLine(message, "piece " + std::to_string(p) + " passes through itself where it is deformed (" +
            std::to_string(crossings) + " pairs of faces cross), as it did there before (" + std::to_string(before) +
            " pairs): it is no valid solid to print");
      else
        addLine(message, "piece " + std::to_string(p) + " passes through itself after its deformations (" +
            std::to_string(crossings) + " pairs of faces cross): it is no valid solid to print; undo (z) or deform less");
    }
    auto deformed = vtkSmartPointer<vtkPolyData>::New();
    deformed->ShallowCopy(f->GetOutput());
    pieces[p] = deformed;
  }
}

void Planner::rebuild()
{
  if (showWork)
  {
    const char* shown = status->GetInput();
    status->SetInput((std::string(shown ? shown : "") + " | working ...").c_str());
    window->Render();
  }
  for (auto& a : sceneActors)
    renderer->RemoveActor(a);
  sceneActors.clear();
  scalarBar->SetVisibility(false);
  computeCut();
  message = inputWarnings;
  if (!cut.message.empty())
    addLine(message, cut.message);
  cutFailed = cut.failed;
  for (const auto& [line, shade] : cut.lines)
    addLineActor(line, shade);
  // Where an open line can be continued: a drag that starts in a marker.
  for (const auto& end : openEnds())
  {
    auto marker = addActorData(ballAt(end, joinTolerance), { 0.95, 0.55, 0.1 }, false);
    marker->GetProperty()->SetOpacity(0.6);
    marker->PickableOff(); // a drag that starts in it picks the bone under it
  }
  applyDeformations();
  resolveNames();
  cutSummary = summaryOfCut();
  if (lattices.size() > pieces.size())
    lattices.resize(pieces.size()); // pieces the cut no longer makes
  pieceActors.assign(pieces.size(), {});
  // Every piece's Metro colours share one scale: the largest of their colour maxima.
  double colourTop = 0.0, largest = 0.0;
  for (std::size_t p = 0; p < pieces.size(); ++p)
  {
    const std::size_t firstActor = sceneActors.size();
    vtkSmartPointer<vtkPolyData> shown = pieces[p];
    FittedLattice* fitted = session.lattice ? &latticeOf(p) : nullptr;
    if (fitted && !fitted->errors.empty())
      addLine(message, "no lattice for piece " + std::to_string(p) + ": " + fitted->errors);
    const bool latticeShown = fitted && fitted->surface->GetNumberOfPoints() > 0;
    if (latticeShown)
    {
      shown = fitted->surface;
      vtkNew<vtkExtractEdges> cage;
      cage->SetInputData(fitted->lattice);
      addActor(cage->GetOutputPort(), nullptr, { 0.2, 0.2, 0.2 }, false)->PickableOff();
    }
    if (session.metro && latticeShown)
    {
      if (!fitted->metro)
      {
        vtkNew<vtkLKMetroFilter> metro;
        metro->SetInputData(fitted->surface);
        metro->SetTargetData(pieces[p]);
        metro->Update();
        fitted->metro = vtkSmartPointer<vtkPolyData>::New();
        fitted->metro->ShallowCopy(metro->GetOutput());
        fitted->metro->GetPointData()->SetActiveScalars("Distance");
        fitted->colourMaximum = metro->GetEffectiveColorMaximum();
        fitted->hausdorff = metro->GetHausdorffDistance();
      }
      auto actor = addActorData(fitted->metro, { 1, 1, 1 }, true);
      actor->GetMapper()->SetLookupTable(distanceColours);
      actor->GetMapper()->UseLookupTableScalarRangeOn();
      colourTop = std::max(colourTop, fitted->colourMaximum);
      largest = std::max(largest, fitted->hausdorff);
      scalarBar->SetVisibility(true);
    }
    else
      addActorData(shown, pieceColour(p), false);
    pieceActors[p].assign(sceneActors.begin() + static_cast<std::ptrdiff_t>(firstActor), sceneActors.end());
  }
  lkapp::distanceColourBar(colourTop, largest, distanceColours, scalarBar);
  if (session.segment >= 0 && pieces.size() < 2)
    addLine(message, "the segment (piece " + std::to_string(session.segment) + ") is not moved: there is no cut");
  else if (session.segment >= static_cast<int>(pieces.size()))
    addLine(message, "the session's segment (piece " + std::to_string(session.segment) + ") does not exist: the plan has " +
      std::to_string(pieces.size()) + " piece(s)");
  // The mirror image, made once per bone.
  for (vtkActor* actor : { mirrorActor.Get(), mirrorPlaneActor.Get(), mirrorPlaneOutline.Get() })
    actor->SetVisibility(false);
  if (session.mirror)
  {
    if (mirrorImage().surface)
      for (vtkActor* actor : { mirrorActor.Get(), mirrorPlaneActor.Get(), mirrorPlaneOutline.Get() })
        actor->SetVisibility(true);
    else
      addLine(message, "no mirror image: " + mirror.error);
  }
  showNames();
  sceneMessage = message;
  showScan();
  placeSegment(session.segmentMatrix); // and the measurements and the fit to the mirror
  keepChanges();
  updateStatus();
}

std::vector<int> Planner::closedCutLines() const
{
  std::vector<int> numbers;
  const std::vector<lkapp::LineFacts> facts = lkapp::lineFacts(cut.loops);
  for (std::size_t k = 0; k < facts.size(); ++k)
    if (facts[k].closed)
      numbers.push_back(static_cast<int>(k) + 1);
  return numbers;
}

bool Planner::scanPictureOf(int number, bool across, double offset, lkapp::ScanPicture& picture, std::string& why)
{
  const std::vector<lkapp::LineFacts> facts = lkapp::lineFacts(cut.loops);
  if (number < 1 || number > static_cast<int>(facts.size()) || !facts[static_cast<std::size_t>(number - 1)].closed)
  {
    why = "the plan has no closed cut line " + std::to_string(number) +
      (facts.empty() ? " (the plan is not cut: x)" : "");
    return false;
  }
  lkapp::ScanPictureRequest request;
  const lkapp::LineFacts& f = facts[static_cast<std::size_t>(number - 1)];
  request.centre = { f.centre[0], f.centre[1], f.centre[2] };
  request.normal = { f.normal[0], f.normal[1], f.normal[2] };
  request.across = across;
  request.softTissue = session.softTissueWindow;
  request.offset = offset;
  request.patientGiven = patientStated();
  request.patient = session.patient;
  request.windowWidth = session.scanWindowWidth;
  request.windowLevel = session.scanWindowLevel;
  for (std::size_t k = 0; k < facts.size(); ++k)
    if (facts[k].closed && static_cast<int>(k) + 1 != number)
      request.otherPlanes.push_back({ { facts[k].centre[0], facts[k].centre[1], facts[k].centre[2] },
        { facts[k].normal[0], facts[k].normal[1], facts[k].normal[2] } });
  auto it = vtk::TakeSmartPointer(cut.loops->GetLines()->NewIterator());
  int k = 1;
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++k)
    if (k == number)
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      for (vtkIdType i = 0; i < n; ++i)
        cut.loops->GetPoint(ids[i], request.line.emplace_back().data());
      break;
    }
  if (!readScanFile(why) || !lkapp::makeScanPicture(scan, scanToPatient, scanIsLabelMap, bone, request, picture, why))
    return false;
  picture.directions = lkapp::coordinateSpace(bone) == "LPS";
  picture.title = scanTitle(picture, number, across, offset);
  return true;
}

std::string Planner::scanTitle(const lkapp::ScanPicture& picture, int number, bool across, double offset) const
{
  return scanText(number, across) + (patientStated() ? ", head up as stated" : "") +
    lkapp::planeOffsetText(picture.frame, offset, picture.directions);
}

bool Planner::patientStated() const
{
  return session.patientGiven && bone && lkapp::coordinateSpace(bone) != "LPS";
}

void Planner::previewScanWindow(double width, double level)
{
  if (!scanRenderer->GetDraw() || !scanPicture.image)
    return;
  scanPicture.grey = lkapp::handWindow(width, level);
  lkapp::showScanPicture(scanRenderer, scanPicture, 12);
}

bool Planner::readScanFile(std::string& why)
{
  if (scanFile.empty())
    return true;
  const std::string file = scanFile;
  scanFile.clear(); // read once, whatever comes of it
  vtkNew<vtkLKMedicalImageReader> reader;
  reader->SetFileName(file.c_str());
  // What the reader says goes into `why`, not the terminal: its warnings
  // (the folder's other series and sets) were said when the plan was read.
  std::string said;
  vtkNew<vtkCallbackCommand> listen;
  listen->SetClientData(&said);
  listen->SetCallback([](vtkObject*, unsigned long event, void* client, void* text) {
    if (event == vtkCommand::ErrorEvent && text)
      *static_cast<std::string*>(client) += (static_cast<std::string*>(client)->empty() ? "" : "; ") +
        lkapp::cleanMessage(static_cast<const char*>(text));
  });
  reader->AddObserver(vtkCommand::ErrorEvent, listen);
  reader->AddObserver(vtkCommand::WarningEvent, listen);
  reader->Update();
  if (!said.empty() || reader->GetOutput()->GetNumberOfPoints() == 0)
  {
    why = "the CT the segmentation was drawn on ('" + file + "') could not be read" + (said.empty() ? "" : ": " + said);
    return false;
  }
  scan = vtkSmartPointer<vtkImageData>::New();
  scan->ShallowCopy(reader->GetOutput());
  scanToPatient->DeepCopy(reader->GetPatientMatrix());
  scanIsLabelMap = false;
  return true;
}

std::string Planner::scanText(int number, bool across) const
{
  return std::string(scanIsLabelMap ? "label map" : "CT") + (across ? " across cut line " : " on cut line ") +
    std::to_string(number) + (across ? "" : "'s plane");
}

std::string Planner::scanShown() const
{
  const std::string window = scanIsLabelMap ? "" :
    session.scanWindowWidth > 0.0 ? lkapp::greyWindowText(lkapp::handWindow(session.scanWindowWidth, session.scanWindowLevel)) :
    session.softTissueWindow      ? " (soft-tissue window)" : "";
  return scanTitle(scanPicture, session.scanOnLine, session.scanAcross, session.scanOffset) + window;
}

void Planner::showScan()
{
  if (session.scanOnLine <= 0)
  {
    scanRenderer->DrawOff();
    renderer->GetActiveCamera()->SetUserTransform(nullptr);
    return;
  }
  const std::string key = cut.key + "|" + std::to_string(session.scanOnLine) + (session.scanAcross ? "|across" : "") +
    (session.softTissueWindow ? "|soft" : "") + "|" + std::to_string(session.scanOffset) + "|" +
    std::to_string(session.scanWindowWidth) + "|" + std::to_string(session.scanWindowLevel);
  if (key != scanShownKey)
  {
    scanShownKey = key;
    scanMovedKey.clear(); // placeSegment, which rebuild calls next, draws it (showScanMoved)
    scanWhy.clear();
    if (!scanPictureOf(session.scanOnLine, session.scanAcross, session.scanOffset, scanPicture, scanWhy))
      scanPicture = lkapp::ScanPicture();
    // What the mouse does there (the exported pictures have no hint).
    scanPicture.hint = scanIsLabelMap ? "wheel: move the plane" : "drag: window | wheel: move the plane";
  }
  if (!scanWhy.empty())
    addLine(message, "no " + scanText(session.scanOnLine, session.scanAcross) + ": " + scanWhy);
  scanRenderer->SetDraw(scanWhy.empty());
  renderer->GetActiveCamera()->SetUserTransform(scanWhy.empty() ? roomForScan.Get() : nullptr);
  showScanPlane();
}

void Planner::refreshScan()
{
  message = sceneMessage; // what the scene said, not the last key's answer
  showScan();
  showScanMoved(session.segmentMatrix);
  keepChanges();
  updateStatus();
}

void Planner::showScanPlane()
{
  const bool shown = scanRenderer->GetDraw() && scanPicture.image;
  for (vtkActor* actor : { scanPlaneSheet.Get(), scanPlaneOutline.Get() })
    actor->SetVisibility(shown);
  if (!shown)
    return;
  // The picture's square, corner by corner around it.
  const lkapp::ViewFrame& f = scanPicture.frame;
  const double half = 0.5 * scanPicture.side;
  vtkNew<vtkPoints> corners;
  for (const auto& [x, y] : { std::make_pair(-half, -half), { half, -half }, { half, half }, { -half, half } })
    corners->InsertNextPoint(f.centre[0] + x * f.right[0] + y * f.up[0], f.centre[1] + x * f.right[1] + y * f.up[1],
      f.centre[2] + x * f.right[2] + y * f.up[2]);
  showSquare(corners, scanPlaneSheet, scanPlaneOutline);
}

std::vector<std::vector<std::array<double, 3>>> Planner::movedSection(
  const lkapp::ViewFrame& frame, const std::array<double, 16>& matrix) const
{
  if (!hasSegment() || isIdentity(matrix))
    return {};
  vtkNew<vtkTransform> move;
  move->SetMatrix(matrix.data());
  vtkNew<vtkTransformPolyDataFilter> moved;
  moved->SetInputData(pieces[static_cast<std::size_t>(movedPiece())]);
  moved->SetTransform(move);
  moved->Update();
  return lkapp::planeSectionLoops(moved->GetOutput(), frame.centre, frame.towardViewer, kBesideACap);
}

void Planner::showScanMoved(const std::array<double, 16>& matrix)
{
  if (!scanRenderer->GetDraw() || !scanPicture.image)
    return;
  std::string key = std::to_string(movedPiece()) +
    (hasSegment() ? " " + std::to_string(pieces[static_cast<std::size_t>(movedPiece())]->GetMTime()) : "");
  if (hasSegment() && !isIdentity(matrix))
    for (double v : matrix)
      key += " " + std::to_string(v);
  lkapp::ScanPicture marks; // the picture's plane and size: a waiting point's cross is sized by it
  marks.frame = scanPicture.frame;
  marks.side = scanPicture.side;
  measuredOnPlane(marks, true);
  std::string measuredKey;
  for (const auto& line : marks.measured)
    for (const auto& q : line)
      measuredKey += std::to_string(q[0]) + " " + std::to_string(q[1]) + " " + std::to_string(q[2]) + ";";
  for (const auto& [at, text] : marks.measuredValues)
    measuredKey += text + ";";
  if (key == scanMovedKey && measuredKey == scanMeasuredKey)
    return;
  if (key != scanMovedKey)
    scanPicture.moved = movedSection(scanPicture.frame, matrix);
  scanMovedKey = key;
  scanMeasuredKey = measuredKey;
  scanPicture.measured = marks.measured;
  scanPicture.measuredValues = marks.measuredValues;
  scanPicture.measuredBeforeMove = marks.measuredBeforeMove;
  lkapp::showScanPicture(scanRenderer, scanPicture, 12);
}

bool Planner::onScanPlane(const std::vector<std::array<double, 3>>& points, const lkapp::ViewFrame& frame)
{
  return std::all_of(points.begin(), points.end(),
    [&](const std::array<double, 3>& q) { return std::abs(lkapp::inFrame(frame, q)[2]) <= kOnScanPlane; });
}

void Planner::measuredOnPlane(lkapp::ScanPicture& picture, bool picking) const
{
  picture.measured.clear();
  picture.measuredValues.clear();
  picture.measuredBeforeMove = false;
  // As picked: the CT is the scan before the segment's move.
  for (const Measurement& m : session.measurements)
  {
    if (!onScanPlane(m.points(), picture.frame))
      continue;
    // The value as picked, on the scan; where the segment's move changes
    // it (the bone's view shows the moved value), the legend says so.
    const std::string text = valueText(m);
    picture.measuredBeforeMove = picture.measuredBeforeMove || text != measuredText(m);
    if (m.angle)
    {
      picture.measured.push_back({ m.from, m.at, m.to });
      picture.measuredValues.emplace_back(m.at, text);
    }
    else
    {
      picture.measured.push_back({ m.from, m.to });
      picture.measuredValues.emplace_back(
        std::array<double, 3>{ 0.5 * (m.from[0] + m.to[0]), 0.5 * (m.from[1] + m.to[1]), 0.5 * (m.from[2] + m.to[2]) },
        text);
    }
  }
  // The points of a measurement under way: small crosses, joined.
  if (!picking || measuring == 0 || settingPlane)
    return;
  std::vector<std::array<double, 3>> waiting;
  for (const auto& q : measurePicked)
    if (onScanPlane({ q }, picture.frame))
    {
      waiting.push_back(q);
      const double arm = 0.015 * picture.side;
      for (const auto& [x, y] : { std::make_pair(1.0, 1.0), std::make_pair(1.0, -1.0) })
      {
        std::array<double, 3> a = q, b = q;
        for (std::size_t i = 0; i < 3; ++i)
        {
          a[i] -= arm * (x * picture.frame.right[i] + y * picture.frame.up[i]);
          b[i] += arm * (x * picture.frame.right[i] + y * picture.frame.up[i]);
        }
        picture.measured.push_back({ a, b });
      }
    }
  if (waiting.size() >= 2)
    picture.measured.push_back(waiting);
}

std::string Planner::scanPictureName(int number, bool across, double offset)
{
  std::string name = "cut_line" + std::to_string(number) + (across ? "_across" : "") + "_ct";
  if (offset != 0.0)
  {
    char mm[32];
    std::snprintf(mm, sizeof mm, "_%+gmm", offset);
    name += mm;
  }
  return name + ".png";
}

bool Planner::writeScanPictures(const std::string& folder, std::vector<std::string>& written, std::string& shown,
  std::string& shownTitle, std::string& error)
{
  written.clear();
  shown.clear();
  shownTitle.clear();
  if (!hasScan())
    return true;
  // Two pictures a closed line, on its plane and across it; and the view as
  // it was shown, where its plane was moved off the cut's (the wheel): the
  // canal beside the cut the surgeon looked at.
  const std::vector<int> lines = closedCutLines();
  std::vector<std::tuple<int, bool, double>> views;
  for (int number : lines)
    for (const bool across : { false, true })
      views.emplace_back(number, across, 0.0);
  if (session.scanOffset != 0.0 && std::find(lines.begin(), lines.end(), session.scanOnLine) != lines.end())
    views.emplace_back(session.scanOnLine, session.scanAcross, session.scanOffset);
  for (const auto& [number, across, offset] : views)
  {
    lkapp::ScanPicture picture;
    std::string why;
    const std::string name = scanPictureName(number, across, offset);
    const bool made = scanPictureOf(number, across, offset, picture, why);
    if (made)
    {
      picture.moved = movedSection(picture.frame, session.segmentMatrix);
      measuredOnPlane(picture, false);
    }
    if (!made ||
      !lkapp::writeScanPicture(picture, 600, folder + "/" + name, why, window->GetGenericDisplayId()))
    {
      // The others are still written.
      error += (error.empty() ? "" : "; ") + ("no " + name + ", the " + scanText(number, across) + ": " + why);
      continue;
    }
    written.push_back(name);
    if (offset != 0.0)
    {
      shown = name;
      shownTitle = picture.title;
    }
  }
  return error.empty();
}

void Planner::keepChanges()
{
  if (std::string error; !keepUnsaved(error))
    addLine(message, "the changes not saved could not be kept (--session sets where): " + error);
}

void Planner::markSaved()
{
  savedSession = sessionText(session);
  std::string error;
  keepUnsaved(error); // only removes the kept copy
}

bool Planner::keepUnsaved(std::string& error)
{
  if (unsavedPath.empty())
    return true;
  const std::string text = sessionText(session);
  if (text == savedSession)
  {
    if (!keptSession.empty())
      std::remove(unsavedPath.c_str()); // only the saved session is left to keep
    keptSession.clear();
    lkapp::setCrashNote("");
    return true;
  }
  if (text == keptSession)
    return true;
  if (!lkapp::writeFileAtomically(unsavedPath, text, error))
    return false;
  keptSession = text;
  // A crash in a later step loses that step only: say where the rest is.
  lkapp::setCrashNote("the plan, as it was after its last finished step, is kept in " + unsavedPath +
    ": open it again with --replay " + unsavedPath);
  return true;
}

std::array<double, 3> Planner::anchorOf(std::size_t p) const
{
  // The point of the piece farthest from every other piece: away from the
  // cut lines and caps (whose points the pieces beside share), so that no
  // other piece of a cut made anew lies as near it.
  vtkNew<vtkPoints> others;
  for (std::size_t q = 0; q < cut.pieces.size(); ++q)
    if (q != p)
      for (vtkIdType i = 0; i < cut.pieces[q]->GetNumberOfPoints(); ++i)
        others->InsertNextPoint(cut.pieces[q]->GetPoint(i));
  vtkPolyData* piece = cut.pieces[p];
  std::array<double, 3> best{ 0, 0, 0 };
  if (piece->GetNumberOfPoints() == 0)
    return best;
  piece->GetPoint(0, best.data());
  if (others->GetNumberOfPoints() == 0)
    return best;
  vtkNew<vtkPolyData> cloud;
  cloud->SetPoints(others);
  vtkNew<vtkStaticPointLocator> locator;
  locator->SetDataSet(cloud);
  locator->BuildLocator();
  double farthest = -1.0;
  for (vtkIdType i = 0; i < piece->GetNumberOfPoints(); ++i)
  {
    double x[3], y[3];
    piece->GetPoint(i, x);
    others->GetPoint(locator->FindClosestPoint(x), y);
    const double d = vtkMath::Distance2BetweenPoints(x, y);
    if (d > farthest)
    {
      farthest = d;
      best = { x[0], x[1], x[2] };
    }
  }
  return best;
}

std::vector<std::vector<double>> Planner::pieceDistances(const std::vector<std::array<double, 3>>& points) const
{
  std::vector<std::vector<double>> distances(points.size(), std::vector<double>(cut.pieces.size(), VTK_DOUBLE_MAX));
  for (std::size_t p = 0; p < cut.pieces.size(); ++p)
  {
    if (cut.pieces[p]->GetNumberOfCells() == 0)
      continue;
    vtkNew<vtkStaticCellLocator> locator;
    locator->SetDataSet(cut.pieces[p]);
    locator->BuildLocator();
    for (std::size_t k = 0; k < points.size(); ++k)
    {
      double closest[3], d2 = 0.0;
      vtkIdType cell = -1;
      int sub = 0;
      locator->FindClosestPoint(points[k].data(), closest, cell, sub, d2);
      distances[k][p] = std::sqrt(d2);
    }
  }
  return distances;
}

int Planner::pieceOnScan(const std::array<double, 3>& point, double& nearest) const
{
  const std::vector<double> distance = pieceDistances({ point }).front();
  const auto best = std::min_element(distance.begin(), distance.end());
  nearest = best == distance.end() ? VTK_DOUBLE_MAX : *best;
  if (nearest == VTK_DOUBLE_MAX)
    return Measurement::kSoftTissue;
  const int piece = static_cast<int>(best - distance.begin());
  if (nearest <= kBesideTheBone)
    return piece;
  // Inside a piece's outline on the plane (any loop counts, so that the
  // marrow inside the cortex's inner wall is bone too); on a cut's own
  // plane, where a piece's cap lies and its section is not defined, inside
  // the uncut bone's.
  const std::array<double, 3>& normal = scanPicture.frame.towardViewer;
  auto encloses = [&](const std::vector<std::vector<std::array<double, 3>>>& loops) {
    for (const auto& loop : loops)
      if (lkapp::loopEncloses(loop, point, normal))
        return true;
    return false;
  };
  for (std::size_t p = 0; p < cut.pieces.size(); ++p)
    if (encloses(lkapp::planeSectionLoops(cut.pieces[p], point, normal, kBesideACap)))
      return static_cast<int>(p);
  return encloses(lkapp::planeSectionLoops(bone, point, normal)) ? piece : Measurement::kSoftTissue;
}

void Planner::resolveNames()
{
  std::vector<std::array<double, 3>> points;
  for (const PieceName& n : session.names)
    points.push_back(n.at);
  // The nearest pieces change with the cut or the points only (a name
  // given, taken away, undone), not at every step.
  if (cut.key != namesCutKey || points != namesAt)
  {
    const std::vector<std::vector<double>> distances =
      points.empty() ? std::vector<std::vector<double>>() : pieceDistances(points);
    nameTargets.assign(session.names.size(), -1);
    for (std::size_t i = 0; i < points.size(); ++i)
    {
      const auto best = std::min_element(distances[i].begin(), distances[i].end());
      if (best != distances[i].end() && *best < VTK_DOUBLE_MAX)
        nameTargets[i] = static_cast<int>(best - distances[i].begin());
    }
    namesCutKey = cut.key;
    namesAt = points;
  }
  for (std::size_t p = 0; p < cut.pieces.size(); ++p)
  {
    const std::string name = pieceName(p);
    for (std::size_t q = p + 1; q < cut.pieces.size() && !name.empty(); ++q)
      if (pieceName(q) == name)
        addLine(message, "piece " + std::to_string(p) + " and piece " + std::to_string(q) + " are both named '" + name +
            "' (the cut numbered them anew): name one again (t)");
  }
}

int Planner::nameIndex(std::size_t p) const
{
  for (std::size_t i = nameTargets.size(); i-- > 0;)
    if (nameTargets[i] == static_cast<int>(p))
      return static_cast<int>(i);
  return -1;
}

std::string Planner::pieceName(std::size_t p) const
{
  const int i = nameIndex(p);
  return i < 0 ? std::string() : session.names[static_cast<std::size_t>(i)].name;
}

void Planner::showNames()
{
  for (const NameCaption& c : nameCaptions)
    renderer->RemoveViewProp(c.actor);
  nameCaptions.clear();
  for (std::size_t p = 0; p < pieces.size(); ++p)
  {
    const int i = nameIndex(p);
    if (i < 0)
      continue;
    const std::string& name = session.names[static_cast<std::size_t>(i)].name;
    auto caption = captionActor(name, { 0.1, 0.1, 0.4 }, 15, { 20, 20 }); // moved to its point by placeSegment
    renderer->AddViewProp(caption);
    nameCaptions.push_back({ static_cast<int>(p), session.names[static_cast<std::size_t>(i)].at, caption });
  }
}

std::string Planner::lengthText(double length)
{
  char text[32];
  std::snprintf(text, sizeof text, "%.2f mm", length);
  return text;
}

double Planner::pixelsFrom(
  vtkRenderer* view, int x, int y, const std::array<double, 3>& a, const std::array<double, 3>& b)
{
  auto onScreen = [&](const std::array<double, 3>& p) {
    double d[3];
    vtkInteractorObserver::ComputeWorldToDisplay(view, p[0], p[1], p[2], d);
    return std::array<double, 2>{ d[0], d[1] };
  };
  const auto from = onScreen(a), to = onScreen(b);
  const double ux = to[0] - from[0], uy = to[1] - from[1], vx = x - from[0], vy = y - from[1];
  const double length2 = ux * ux + uy * uy;
  const double t = length2 > 0.0 ? std::clamp((ux * vx + uy * vy) / length2, 0.0, 1.0) : 0.0;
  return std::hypot(vx - t * ux, vy - t * uy);
}

int Planner::measurementAt(int x, int y, double pixels, double& distance) const
{
  int best = -1;
  distance = pixels;
  // On the CT view: the measurements drawn there, on its plane as picked,
  // in the picture's coordinates (mm along its right and up).
  const bool onScan = onScanView(x, y);
  const lkapp::ViewFrame& frame = scanPicture.frame;
  auto inPicture = [&](const std::array<double, 3>& q) {
    const std::array<double, 3> f = lkapp::inFrame(frame, q);
    return std::array<double, 3>{ f[0], f[1], 0.0 };
  };
  for (std::size_t i = 0; i < session.measurements.size(); ++i)
  {
    const Measurement& m = session.measurements[i];
    if (onScan && (!scanPicture.image || !onScanPlane(m.points(), frame)))
      continue; // not drawn on the view (measuredOnPlane's rule)
    Measurement shown = onScan ? m : placed(m, shownMatrix);
    if (onScan)
    {
      shown.from = inPicture(shown.from);
      shown.to = inPicture(shown.to);
      shown.at = inPicture(shown.at);
    }
    vtkRenderer* view = onScan ? scanRenderer.Get() : renderer.Get();
    const double d = shown.angle
      ? std::min(pixelsFrom(view, x, y, shown.from, shown.at), pixelsFrom(view, x, y, shown.at, shown.to))
      : pixelsFrom(view, x, y, shown.from, shown.to);
    if (d <= distance)
    {
      distance = d;
      best = static_cast<int>(i);
    }
  }
  return best;
}

int Planner::strokeAt(int x, int y, double pixels, double& distance) const
{
  int best = -1;
  distance = pixels;
  if (onScanView(x, y))
    return best;
  for (std::size_t l = 0; l < cut.lines.size() && l < cut.lineStrokes.size(); ++l)
  {
    vtkPolyData* line = cut.lines[l].first;
    if (!line || !line->GetLines())
      continue;
    auto it = vtk::TakeSmartPointer(line->GetLines()->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType n = 0;
      const vtkIdType* ids = nullptr;
      it->GetCurrentCell(n, ids);
      for (vtkIdType k = 0; k + 1 < n; ++k)
      {
        std::array<double, 3> a, b;
        line->GetPoint(ids[k], a.data());
        line->GetPoint(ids[k + 1], b.data());
        const double d = pixelsFrom(renderer, x, y, a, b);
        if (d <= distance)
        {
          distance = d;
          best = static_cast<int>(cut.lineStrokes[l]);
        }
      }
    }
  }
  return best;
}

int Planner::deformationAt(int piece, const std::array<double, 3>& point) const
{
  for (std::size_t i = session.deformations.size(); i-- > 0;)
  {
    const Deformation& d = session.deformations[i];
    if (d.piece != piece)
      continue;
    // What it moved, moved: its ball or cube swept along its normal by its
    // amount (a dab's amount is 0).
    std::array<double, 3> move;
    for (std::size_t k = 0; k < 3; ++k)
      move[k] = d.tool == "smooth" ? 0.0 : d.amount * d.normal[k];
    if (d.tool == "box")
    {
      // The sweep's steps s in [0, 1] that put the point in the cube.
      double low = 0.0, high = 1.0;
      for (std::size_t k = 0; k < 3 && low <= high; ++k)
      {
        const double off = point[k] - d.centre[k];
        if (move[k] == 0.0)
        {
          if (std::abs(off) > d.radius)
            high = -1.0;
          continue;
        }
        const double a = (off - d.radius) / move[k], b = (off + d.radius) / move[k];
        low = std::max(low, std::min(a, b));
        high = std::min(high, std::max(a, b));
      }
      if (low <= high)
        return static_cast<int>(i);
      continue;
    }
    // A ball swept along a segment: a capsule.
    const double length2 = vtkMath::Dot(move.data(), move.data());
    std::array<double, 3> off{ point[0] - d.centre[0], point[1] - d.centre[1], point[2] - d.centre[2] };
    const double s = length2 > 0.0 ? std::clamp(vtkMath::Dot(off.data(), move.data()) / length2, 0.0, 1.0) : 0.0;
    for (std::size_t k = 0; k < 3; ++k)
      off[k] -= s * move[k];
    if (vtkMath::Dot(off.data(), off.data()) <= d.radius * d.radius)
      return static_cast<int>(i);
  }
  return -1;
}

std::pair<std::size_t, std::size_t> Planner::deformationGroup(std::size_t i) const
{
  const auto& all = session.deformations;
  std::pair<std::size_t, std::size_t> group{ i, i };
  if (i >= all.size() || all[i].tool != "smooth")
    return group;
  // Dabs a and b = a + 1 are of one stroke.
  const auto joined = [&all](std::size_t a) {
    const Deformation& d = all[a];
    const Deformation& e = all[a + 1];
    return d.tool == "smooth" && e.tool == "smooth" && d.piece == e.piece &&
      vtkMath::Distance2BetweenPoints(d.centre.data(), e.centre.data()) <= e.radius * e.radius;
  };
  while (group.first > 0 && joined(group.first - 1))
    --group.first;
  while (group.second + 1 < all.size() && joined(group.second))
    ++group.second;
  return group;
}

void Planner::removeDeformation(std::size_t i)
{
  if (i >= session.deformations.size())
    return;
  const auto group = deformationGroup(i);
  const Deformation& d = session.deformations[i];
  const std::size_t count = group.second - group.first + 1;
  if (count == 1)
    notice = "deformation " + std::to_string(i) + " (" + d.tool + " on piece " + std::to_string(d.piece) + ") removed";
  else
    notice = "deformations " + std::to_string(group.first) + " to " + std::to_string(group.second) +
      " (a smoothing brush stroke on piece " + std::to_string(d.piece) + ", " + std::to_string(count) + " dabs) removed";
  notice += " (z: back)";
  remember();
  session.deformations.erase(session.deformations.begin() + static_cast<std::ptrdiff_t>(group.first),
    session.deformations.begin() + static_cast<std::ptrdiff_t>(group.second + 1));
}

void Planner::showMeasurements()
{
  for (const auto& c : measureCaptions)
    renderer->RemoveViewProp(c);
  measureCaptions.clear();
  if (measureActor)
    overlay->RemoveActor(measureActor);
  measureActor = nullptr;
  // The points clicked so far, while the next is awaited.
  measureMarker->SetVisibility(measuring && !measurePicked.empty());
  if (measuring && !measurePicked.empty())
  {
    vtkNew<vtkAppendPolyData> balls;
    for (std::size_t k = 0; k < measurePicked.size(); ++k)
      balls->AddInputData(ballAt(shownPoint(measurePicked[k], measurePickedPieces[k], shownMatrix), 0.5 * joinTolerance));
    balls->Update();
    vtkPolyDataMapper::SafeDownCast(measureMarker->GetMapper())->SetInputData(balls->GetOutput());
  }
  showScanMoved(shownMatrix); // and on the CT view, what lies on its plane
  if (session.measurements.empty())
    return;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines, ends;
  for (const Measurement& m : session.measurements)
  {
    const Measurement shown = placed(m, shownMatrix);
    const vtkIdType a = points->InsertNextPoint(shown.from.data());
    const vtkIdType b = points->InsertNextPoint(shown.to.data());
    ends->InsertNextCell(1, &a);
    ends->InsertNextCell(1, &b);
    // A distance's line, with its length below its middle (beside where a
    // name's caption would be); an angle's arms, with its degrees at its
    // vertex.
    std::array<double, 3> label;
    if (m.angle)
    {
      const vtkIdType c = points->InsertNextPoint(shown.at.data());
      const vtkIdType arms[3] = { a, c, b };
      lines->InsertNextCell(3, arms);
      ends->InsertNextCell(1, &c);
      label = shown.at;
    }
    else
    {
      const vtkIdType ids[2] = { a, b };
      lines->InsertNextCell(2, ids);
      for (std::size_t k = 0; k < 3; ++k)
        label[k] = 0.5 * (shown.from[k] + shown.to[k]);
    }
    const std::string text = valueText(shown);
    auto caption = captionActor(text, { 0.45, 0.0, 0.4 }, 14, { 15, -30 });
    caption->SetAttachmentPoint(label.data());
    renderer->AddViewProp(caption);
    measureCaptions.push_back(caption);
  }
  vtkNew<vtkPolyData> shown;
  shown->SetPoints(points);
  shown->SetLines(lines);
  shown->SetVerts(ends);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(shown);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(0.55, 0.0, 0.45);
  actor->GetProperty()->SetLineWidth(3);
  actor->GetProperty()->SetPointSize(9);
  actor->GetProperty()->RenderPointsAsSpheresOn();
  actor->PickableOff();
  overlay->AddActor(actor);
  measureActor = actor;
}

std::string Planner::pieceLabel(std::size_t p) const
{
  const std::string name = pieceName(p);
  return "piece " + std::to_string(p) + (name.empty() ? "" : " '" + name + "'");
}

bool Planner::namePiece(std::size_t p, const std::array<double, 3>& at, const std::string& name, std::string& why)
{
  why.clear();
  if (!name.empty() && !validPieceName(name, why))
    return false;
  for (std::size_t q = 0; q < cut.pieces.size() && !name.empty(); ++q)
    if (q != p && pieceName(q) == name)
    {
      why = "piece " + std::to_string(q) + " is named '" + name + "' already";
      return false;
    }
    else if (q != p && pieceName(q).empty() && name == "piece " + std::to_string(q))
    {
      why = "'" + name + "' is what piece " + std::to_string(q) + " goes by in the structure set";
      return false;
    }
  remember();
  std::vector<PieceName> kept;
  for (std::size_t i = 0; i < session.names.size(); ++i)
    if (i >= nameTargets.size() || nameTargets[i] != static_cast<int>(p))
      kept.push_back(session.names[i]);
  if (!name.empty())
    kept.push_back({ name, at });
  session.names = kept;
  return true;
}

void Planner::followPieces()
{
  const bool segmentFollows = session.segment >= 0 && session.segmentAnchored && cut.pieces.size() >= 2;
  if (!segmentFollows && session.deformations.empty() && session.measurements.empty())
    return; // without a cut the segment keeps its number for the cut's return
  // One locator per piece serves the segment's point, every centre and
  // every measured end.
  std::vector<std::array<double, 3>> points;
  for (const Deformation& d : session.deformations)
    points.push_back(d.centre);
  std::vector<std::size_t> firstPoint; // each measurement's first point in `points`
  for (const Measurement& m : session.measurements)
  {
    firstPoint.push_back(points.size());
    for (const auto& x : m.points())
      points.push_back(x);
  }
  points.push_back(session.segmentAnchor);
  const std::vector<std::vector<double>> distances = pieceDistances(points);
  double diagonal = 0.0;
  for (const auto& piece : cut.pieces)
    diagonal = std::max(diagonal, piece->GetLength());
  // The nearest piece, or `own` when that is as near (a point on a cut line
  // lies on both pieces).
  auto nearest = [&](const std::vector<double>& distance, int own) {
    const auto best = static_cast<int>(std::min_element(distance.begin(), distance.end()) - distance.begin());
    const bool exists = own >= 0 && own < static_cast<int>(distance.size());
    const double ownDistance = exists ? distance[static_cast<std::size_t>(own)] : VTK_DOUBLE_MAX;
    return best != own && distance[static_cast<std::size_t>(best)] < ownDistance - 1e-9 * diagonal ? best : own;
  };
  if (segmentFollows)
  {
    const int best = nearest(distances.back(), session.segment);
    if (best != session.segment)
    {
      notice = "the cut numbers its pieces anew: the segment is now piece " + std::to_string(best);
      session.segment = best;
    }
  }
  std::string moved;
  std::vector<double> movedBefore(cut.pieces.size(), 0.0); // how far earlier deformations can have moved each piece
  for (std::size_t i = 0; i < session.deformations.size(); ++i)
  {
    Deformation& d = session.deformations[i];
    const std::vector<double>& distance = distances[i];
    const int best = nearest(distance, d.piece);
    if (best != d.piece)
    {
      moved += (moved.empty() ? "" : ", ") + std::to_string(i) + " to piece " + std::to_string(best);
      d.piece = best;
    }
    // Beyond its reach from every piece (a hand-made or stale session), it
    // would move nothing without a word. A box reaches its corners. It acts
    // on the piece as the deformations before it left it (a dab picked on a
    // bump lies off the cut piece), so their largest moves count too.
    if (d.piece < 0 || d.piece >= static_cast<int>(distance.size()) || distance[static_cast<std::size_t>(d.piece)] == VTK_DOUBLE_MAX)
      continue; // no such piece (applyDeformations says so), or an empty one
    const double away = distance[static_cast<std::size_t>(d.piece)];
    double& before = movedBefore[static_cast<std::size_t>(d.piece)];
    const double reach = (d.tool == "box" ? std::sqrt(3.0) * d.radius : d.radius) + before;
    before += d.tool == "smooth" ? d.radius : std::abs(d.amount);
    if (away > reach)
    {
      char line[200];
      std::snprintf(line, sizeof line, "deformation %zu (%s) lies %.1f mm from piece %d, beyond its radius %.1f mm: it moves nothing",
        i, d.tool.c_str(), away, d.piece, d.radius);
      addLine(cut.message, line);
    }
  }
  if (!moved.empty())
    notice += (notice.empty() ? "" : "; ") + std::string("the deformations follow their pieces: ") + moved;
  // Each measured point goes with its piece, as the segment's move shows it;
  // a point of the soft tissue (measured on the CT) with none, as measured.
  for (std::size_t i = 0; i < session.measurements.size(); ++i)
  {
    Measurement& m = session.measurements[i];
    for (std::size_t k = 0; k < m.points().size(); ++k)
      if (m.pieces[k] != Measurement::kSoftTissue)
        m.pieces[k] = nearest(distances[firstPoint[i] + k], m.pieces[k]);
  }
}

std::string Planner::summaryOfCut()
{
  if (!cut.loops)
    return "";
  std::ostringstream s;
  s.setf(std::ios::fixed);
  const std::vector<lkapp::LineFacts> lines = lkapp::lineFacts(cut.loops);
  s.precision(1);
  s << "cut lines:";
  for (std::size_t k = 0; k < lines.size(); ++k)
    s << (k ? "," : "") << " " << k + 1 << ": " << lines[k].length << " mm";
  for (std::size_t j = 0; j < lines.size(); ++j)
    for (std::size_t k = j + 1; k < lines.size(); ++k)
    {
      const lkapp::LinesApart apart = lkapp::linesApart(lines[j], lines[k]);
      s << " | " << j + 1 << "-" << k + 1 << ": " << apart.distance << " mm apart, " << apart.degrees << " deg";
    }
  s.precision(2);
  s << " | pieces:";
  for (std::size_t p = 0; p < pieces.size(); ++p)
  {
    const lkapp::PieceFacts& f = factsOf(p);
    const std::string name = pieceName(p);
    s << (p ? "," : "") << " " << p << (name.empty() ? "" : " '" + name + "'") << ": ";
    if (f.openEdges == 0)
      s << f.volume / 1000.0 << " ml";
    else
      s << "open";
  }
  return s.str();
}

const lkapp::PieceFacts& Planner::factsOf(std::size_t p)
{
  if (pieceFacts.size() != pieces.size())
    pieceFacts.resize(pieces.size());
  KeptFacts& kept = pieceFacts[p];
  // The MTime is global and only grows: a new object never repeats an old
  // one's pointer and time together.
  if (kept.piece != pieces[p].Get() || kept.time != pieces[p]->GetMTime())
  {
    kept.piece = pieces[p];
    kept.time = pieces[p]->GetMTime();
    kept.facts = lkapp::pieceFacts(pieces[p]);
  }
  return kept.facts;
}

Planner::FittedLattice& Planner::latticeOf(std::size_t p)
{
  vtkPolyData* piece = pieces[p];
  // The cut piece's feature edges, on the piece as its deformations left it.
  FeatureEdges features;
  std::size_t refined = 0;
  if (p < cut.featureEdges.size())
  {
    features = cut.featureEdges[p];
    if (piece != cut.pieces[p].Get())
      features = onDeformed(features, piece, cut.pieces[p]->GetNumberOfPoints(), refined);
  }
  // Every vertex of those lines is a lattice vertex: the rest of the bone
  // keeps at least as many (as the main job asks of its plan), or a long
  // split line would leave it a few coarse faces.
  std::set<vtkIdType> onLines;
  for (const auto& e : features)
    onLines.insert(e.begin(), e.end());
  const vtkIdType wanted = std::max<vtkIdType>(session.latticeVertices, 2 * static_cast<vtkIdType>(onLines.size()));
  const vtkIdType vertices = std::min<vtkIdType>(wanted, piece->GetNumberOfPoints() / 2);
  const std::uint64_t key = geometryKey(piece, vertices, features);
  if (lattices.size() <= p)
    lattices.resize(p + 1);
  FittedLattice& fitted = lattices[p];
  if (fitted.lattice && fitted.key == key)
  {
    ++latticesReused;
    return fitted;
  }
  ++latticeFits;
  vtkNew<vtkLKLatticeFitFilter> fit;
  fit->SetInputData(piece);
  fit->SetTargetNumberOfVertices(vertices);
  if (!features.empty())
  {
    vtkNew<vtkPolyData> lines;
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> cells;
    vtkNew<vtkIdTypeArray> ids;
    ids->SetName("MeshPointId");
    for (const auto& e : features)
    {
      cells->InsertNextCell(2);
      for (const vtkIdType v : e)
      {
        cells->InsertCellPoint(points->InsertNextPoint(piece->GetPoint(v)));
        ids->InsertNextValue(v);
      }
    }
    lines->SetPoints(points);
    lines->SetLines(cells);
    lines->GetPointData()->AddArray(ids);
    fit->SetFeatureLinesData(lines);
    fit->LockFeaturesOn();
  }
  fit->QuadPairingOn();
  fit->ComputeErrorOff();
  vtkNew<vtkLKLatticeSurfaceFilter> smooth;
  smooth->SetInputConnection(fit->GetOutputPort());
  smooth->SetResolution(4);
  const int before = lkapp::errorCount();
  smooth->Update();
  fitted.key = key;
  fitted.errors = lkapp::errorCount() > before ? lkapp::errorsSince(before) : "";
  fitted.featureEdges = features.size();
  fitted.featureEdgesRefined = refined;
  fitted.lineVertices = onLines.size();
  fitted.raised = wanted > session.latticeVertices;
  fitted.lattice = vtkSmartPointer<vtkPolyData>::New();
  fitted.lattice->ShallowCopy(fit->GetOutput());
  fitted.surface = vtkSmartPointer<vtkPolyData>::New();
  fitted.surface->ShallowCopy(smooth->GetOutput());
  fitted.metro = nullptr;
  return fitted;
}

std::uint64_t Planner::geometryKey(vtkPolyData* pd, vtkIdType count, const FeatureEdges& edges)
{
  std::uint64_t h = 1469598103934665603ULL;
  auto mix = [&h](const void* data, std::size_t bytes) {
    const auto* c = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; i += 8)
    {
      std::uint64_t word = 0;
      std::memcpy(&word, c + i, std::min<std::size_t>(8, bytes - i));
      word = (word ^ (word >> 30)) * 0xbf58476d1ce4e5b9ULL;
      word = (word ^ (word >> 27)) * 0x94d049bb133111ebULL;
      word ^= word >> 31;
      h = (h ^ word) * 1099511628211ULL;
    }
  };
  mix(&count, sizeof count);
  const vtkIdType n = pd->GetNumberOfPoints();
  mix(&n, sizeof n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    pd->GetPoint(i, x);
    mix(x, sizeof x);
  }
  auto it = vtk::TakeSmartPointer(pd->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType size;
    const vtkIdType* ids;
    it->GetCurrentCell(size, ids);
    mix(&size, sizeof size);
    mix(ids, sizeof(vtkIdType) * static_cast<std::size_t>(size));
  }
  const std::size_t edgeCount = edges.size();
  mix(&edgeCount, sizeof edgeCount);
  if (!edges.empty())
    mix(edges.data(), sizeof(edges[0]) * edges.size());
  return h;
}

vtkSmartPointer<vtkPolyData> Planner::facesOnly(vtkPolyData* surface)
{
  auto faces = vtkSmartPointer<vtkPolyData>::New();
  faces->ShallowCopy(surface);
  vtkNew<vtkCellArray> none;
  faces->SetLines(none);
  return faces;
}

vtkSmartPointer<vtkActor> Planner::addActorData(vtkPolyData* pd, std::array<double, 3> colour, bool scalars)
{
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(pd);
  return addActor(normals->GetOutputPort(), pd, colour, scalars);
}

vtkSmartPointer<vtkActor> Planner::addActor(vtkAlgorithmOutput* port, vtkPolyData*, std::array<double, 3> colour, bool scalars)
{
  vtkNew<vtkPolyDataMapper> m;
  m->SetInputConnection(port);
  m->SetScalarVisibility(scalars);
  auto a = vtkSmartPointer<vtkActor>::New();
  a->SetMapper(m);
  a->GetProperty()->SetColor(colour.data());
  renderer->AddActor(a);
  sceneActors.push_back(a);
  return a;
}

void Planner::addLineActor(vtkPolyData* line, double shade)
{
  vtkNew<vtkPolyDataMapper> m;
  m->SetInputData(line);
  m->ScalarVisibilityOff();
  auto a = vtkSmartPointer<vtkActor>::New();
  a->SetMapper(m);
  a->GetProperty()->SetColor(0.1 + shade, 0.5, 0.1);
  a->GetProperty()->SetLineWidth(3);
  a->PickableOff(); // the lines lie on the bone; strokes and presses pick the bone
  renderer->AddActor(a);
  sceneActors.push_back(a);
}

void Planner::updateStatus()
{
  std::ostringstream s;
  s << (sawing ? "SAW (drag across the bone)" : drawing ? "DRAW" : "view") << " | mode: " << modeName(mode) << " | strokes: " << session.strokes.size()
    << " | pieces: " << pieces.size() << (cut.innerWallLines > 0 ? " (cut through the marrow cavity too)" : "")
    << (session.lattice ? " | lattice" : "")
    << (session.metro ? (session.lattice ? " | Metro colours" : " | Metro colours (on the lattice: press l)") : "")
    << (scanRenderer->GetDraw() ? " | " + scanShown() : "");
  if (session.mirror && mirror.surface)
  {
    char text[120];
    if (segmentToMirror.valid)
      std::snprintf(text, sizeof text, " | mirror image: the segment %.2f mm from it", segmentToMirror.mean);
    else
      std::snprintf(text, sizeof text, " | mirror image: the bone %.2f mm from it", mirror.mean);
    s << text;
  }
  if (tool != NO_TOOL)
  {
    char r[32];
    std::snprintf(r, sizeof r, "%.1f", radius);
    s << " | DEFORM " << toolName(tool) << ", radius " << r
      << (tool == SMOOTH ? " (drag to brush)" : " (drag up/down)");
  }
  if (!session.deformations.empty())
    s << " | deformations: " << session.deformations.size();
  if (naming == 1)
    s << " | NAME: click a piece (Escape: stop)";
  else if (naming == 2)
    s << " | NAME " << pieceLabel(static_cast<std::size_t>(namingPiece)) << ": " << namingText << composer.pending()
      << "_ (Return keeps it, an empty name takes it away; Escape: stop)";
  // With the CT view shown, its plane's points can be measured too.
  const std::string where = scanRenderer->GetDraw() && measuring && !settingPlane ? " on the bone or the CT" : "";
  if (measuring == 2)
    s << " | MEASURE: click the " << (measurePicked.empty() ? "first" : "second") << " point" << where << " (u: stop)";
  else if (measuring == 3 && settingPlane)
    s << " | MIRROR PLANE: click a point of the bone's midline, " << measurePicked.size() + 1
      << " of 3 (O again: the fitted plane; Escape: stop)";
  else if (measuring == 3)
    s << (measurePicked.empty()       ? " | ANGLE: click an arm's end"
            : measurePicked.size() == 1 ? " | ANGLE: click the vertex"
                                        : " | ANGLE: click the other arm's end")
      << where << " (a: stop)";
  else if (!session.measurements.empty())
    s << " | measured: " << measuredText(session.measurements.back())
      << (session.measurements.size() > 1 ? " (last of " + std::to_string(session.measurements.size()) + ")" : "");
  if (typingLattice)
    s << " | LATTICE: " << latticeText << "_ vertices per piece (now " << session.latticeVertices
      << "; Escape: stop)";
  else if (typingMove)
    s << " | MOVE segment " << session.segment << " BY: " << moveText << "_ (x y z mm, then rx ry rz deg to turn"
      << (axesText.empty() ? "" : "; " + axesText) << "; Return; Escape: stop)";
  else if (moving)
    s << " | MOVE segment " << session.segment << " (drag; shift+drag rotates)";
  else if (hasSegment())
    s << " | segment: " << pieceLabel(static_cast<std::size_t>(session.segment))
      << (isIdentity(session.segmentMatrix) ? "" : " (moved)");
  if (const std::string contact = contactStatus(); !contact.empty() && !typingMove)
    s << ", " << contact;
  if (!notice.empty())
    s << " | " << notice;
  if (!cutSummary.empty())
    s << "\n" << cutSummary;
  const std::string statusText = wrapped(s.str(), 130); // the window is 1000 pixels wide
  const std::string messageText = wrapped(message, 120);
  lkapp::useFontFor(status->GetTextProperty(), statusText); // names in any script
  lkapp::useFontFor(messages->GetTextProperty(), messageText);
  status->SetInput(statusText.c_str());
  messages->SetInput(messageText.c_str());
}

void Planner::showStroke()
{
  // A line cell needs two points: a stroke of one point (a click) is a
  // vertex cell, and an empty one has no cell (a line of fewer points
  // leaves the polydata's cell map unbuildable, which crashed a pick).
  vtkNew<vtkPoints> pts;
  vtkNew<vtkCellArray> lines, verts;
  vtkCellArray* cells = current.size() >= 2 ? lines.Get() : verts.Get();
  if (!current.empty())
    cells->InsertNextCell(static_cast<vtkIdType>(current.size()));
  for (const auto& p : current)
    cells->InsertCellPoint(pts->InsertNextPoint(p.data()));
  strokePd->SetPoints(pts);
  strokePd->SetLines(lines);
  strokePd->SetVerts(verts);
  strokePd->Modified();
}

void Planner::checkReplayedInput(bool replayed)
{
  const std::string file = vtksys::SystemTools::GetFilenameName(input);
  std::array<double, 6> b{};
  bone->GetBounds(b.data());
  if (replayed)
  {
    const double diagonal = std::hypot(b[1] - b[0], b[3] - b[2], b[5] - b[4]);
    double shift = 0.0;
    for (std::size_t i = 0; session.inputBoundsKnown && i < 6; ++i)
      shift = std::max(shift, std::abs(b[i] - session.inputBounds[i]));
    const bool otherFile = !session.inputFile.empty() && session.inputFile != file;
    // The same file and settings give the same bone to the last digit; 1 %
    // of its size is another scan (or another surface of it).
    const bool otherBone = session.inputBoundsKnown && shift > 0.01 * diagonal;
    inputWarnings.clear();
    if (otherFile || otherBone)
    {
      char mm[64];
      std::snprintf(mm, sizeof mm, "%.1f", shift);
      inputWarnings = "the session was drawn on " +
        (otherFile ? "'" + session.inputFile + "', not on '" + file + "'" : std::string("another surface")) +
        (otherBone ? std::string(" (the bones' bounds differ by up to ") + mm + " mm)" : "") +
        ": check that this is the same patient's scan before using the plan";
    }
  }
  session.inputFile = file;
  session.inputBounds = b;
  session.inputBoundsKnown = true;
}

std::string Planner::planText()
{
  std::string text;
  char line[400];
  std::snprintf(line, sizeof line, "strokes: %zu\npieces: %zu\n", session.strokes.size(), pieces.size());
  text += line;
  if (cut.innerWallLines > 0)
  {
    std::snprintf(line, sizeof line, "inner wall lines: %d (the cut went through the marrow cavity too)\n",
      cut.innerWallLines);
    text += line;
  }
  for (std::size_t p = 0; p < pieces.size(); ++p)
  {
    std::snprintf(line, sizeof line, "%s: %lld points, %lld faces%s", pieceLabel(p).c_str(),
      static_cast<long long>(pieces[p]->GetNumberOfPoints()), static_cast<long long>(pieces[p]->GetNumberOfPolys()),
      lkapp::pieceFactsText(factsOf(p)).c_str());
    text += line;
    if (vtkDataArray* d = pieces[p]->GetPointData()->GetArray("Displacement"))
    {
      std::snprintf(line, sizeof line, ", deformed: largest displacement %.3f, refinement levels 0-%d", d->GetMaxNorm(),
        static_cast<int>(pieces[p]->GetCellData()->GetArray("Level")->GetRange()[1]));
      text += line;
      if (const vtkIdType crossings = static_cast<vtkIdType>(lkapp::fieldValue(pieces[p], "SelfCrossings")))
      {
        std::snprintf(line, sizeof line, ", passes through itself: %lld pairs of faces cross",
          static_cast<long long>(crossings));
        text += line;
        if (const vtkIdType before = static_cast<vtkIdType>(lkapp::fieldValue(pieces[p], "SelfCrossingsBefore")))
        {
          std::snprintf(line, sizeof line, " (%lld before its deformations)", static_cast<long long>(before));
          text += line;
        }
      }
    }
    text += "\n";
  }
  if (cut.loops)
    text += lkapp::lineFactsText(lkapp::lineFacts(cut.loops), lkapp::coordinateSpace(bone) == "LPS");
  for (std::size_t i = 0; i < session.strokes.size(); ++i)
  {
    const Stroke& st = session.strokes[i];
    if (!st.saw)
      continue;
    const double length = std::hypot(st.sawNormal[0], st.sawNormal[1], st.sawNormal[2]);
    std::snprintf(line, sizeof line, "saw plane of stroke %zu: through (%.2f, %.2f, %.2f), normal (%.3f, %.3f, %.3f)\n",
      i + 1, st.sawOrigin[0], st.sawOrigin[1], st.sawOrigin[2], st.sawNormal[0] / length, st.sawNormal[1] / length,
      st.sawNormal[2] / length);
    text += line;
  }
  for (std::size_t i = 0; i < session.deformations.size(); ++i)
  {
    const Deformation& d = session.deformations[i];
    std::snprintf(line, sizeof line, "deformation %zu: %s on piece %d at (%.2f, %.2f, %.2f), radius %.2f", i,
      d.tool.c_str(), d.piece, d.centre[0], d.centre[1], d.centre[2], d.radius);
    text += line;
    if (d.tool == "smooth")
      std::snprintf(line, sizeof line, ", %d iterations\n", d.iterations);
    else
      std::snprintf(line, sizeof line, ", amount %.3f\n", d.amount);
    text += line;
  }
  // The lattices shown (l): their size, what they keep exactly, how close.
  for (std::size_t p = 0; session.lattice && p < pieces.size() && p < lattices.size(); ++p)
  {
    const FittedLattice& fitted = lattices[p];
    if (!fitted.lattice || !fitted.surface || fitted.surface->GetNumberOfPoints() == 0)
      continue; // a failed fit: its message says why
    std::snprintf(line, sizeof line, "lattice of %s: %.0f control vertices", pieceLabel(p).c_str(),
      lkapp::fieldValue(fitted.lattice, "ControlVertices"));
    text += line;
    if (fitted.raised)
    {
      std::snprintf(line, sizeof line, " (above the session's %ld: its lines take %zu, and the rest of the bone as many)",
        session.latticeVertices, fitted.lineVertices);
      text += line;
    }
    std::snprintf(line, sizeof line, ", %.0f triangles, %.0f quads", lkapp::fieldValue(fitted.lattice, "Triangles"),
      lkapp::fieldValue(fitted.lattice, "Quads"));
    text += line;
    if (fitted.featureEdges > 0)
    {
      std::snprintf(line, sizeof line, "; its cut and stroke lines kept exactly as lattice edges (%zu edge%s)",
        fitted.featureEdges, fitted.featureEdges == 1 ? "" : "s");
      text += line;
    }
    if (fitted.featureEdgesRefined > 0)
    {
      std::snprintf(line, sizeof line, "; %zu edge%s of those lines that a deformation changed %s not kept",
        fitted.featureEdgesRefined, fitted.featureEdgesRefined == 1 ? "" : "s",
        fitted.featureEdgesRefined == 1 ? "is" : "are");
      text += line;
    }
    if (fitted.metro)
    {
      std::snprintf(line, sizeof line, "; Metro distance to the piece: %.3f mm at most, %.3f mm on average",
        lkapp::fieldValue(fitted.metro, "Hausdorff_Max"), lkapp::fieldValue(fitted.metro, "Hausdorff_Mean"));
      text += line;
    }
    text += "\n";
  }
  for (std::size_t i = 0; i < session.measurements.size(); ++i)
  {
    const Measurement& m = session.measurements[i];
    const Measurement shown = placed(m, session.segmentMatrix);
    const std::string value = valueText(shown);
    if (m.angle)
      std::snprintf(line, sizeof line, "measurement %zu: angle %s at (%.2f, %.2f, %.2f) between (%.2f, %.2f, %.2f) and (%.2f, %.2f, %.2f)",
        i + 1, value.c_str(), shown.at[0], shown.at[1], shown.at[2], shown.from[0], shown.from[1], shown.from[2],
        shown.to[0], shown.to[1], shown.to[2]);
    else
      std::snprintf(line, sizeof line, "measurement %zu: %s from (%.2f, %.2f, %.2f) to (%.2f, %.2f, %.2f)", i + 1,
        value.c_str(), shown.from[0], shown.from[1], shown.from[2], shown.to[0], shown.to[1], shown.to[2]);
    text += line;
    // A point on the moved segment moved with it: the value as picked too,
    // where the move changed it.
    const std::string picked = valueText(m);
    if (picked != value)
      text += ", " + picked + " before the segment's move";
    // Points of the soft tissue, measured on the CT: the plan moves bone only.
    const char* ends[2][3] = { { "its first point", "its second point", "" },
      { "arm 1's end", "arm 2's end", "the vertex" } };
    std::string outside;
    for (std::size_t k = 0; k < m.points().size(); ++k)
      if (m.pieces[k] == Measurement::kSoftTissue)
        outside += (outside.empty() ? "" : " and ") + std::string(ends[m.angle ? 1 : 0][k]);
    if (!outside.empty())
      text += ", " + outside + " in the soft tissue (not moved)";
    text += "\n";
  }
  text += segmentText();
  text += mirrorText();
  // What the cut said (why it failed, a failed stroke) belongs to the plan
  // even when a later key's answer took its place in the window's message.
  std::vector<std::string> said;
  for (const std::string* from : { &inputWarnings, &cut.message, &message })
  {
    std::istringstream lines(*from);
    for (std::string m; std::getline(lines, m);)
      if (!m.empty() && std::find(said.begin(), said.end(), m) == said.end())
        said.push_back(m);
  }
  for (const std::string& m : said)
    text += "message: " + m + "\n";
  return text;
}

void Planner::report()
{
  std::printf("%s", planText().c_str());
  if (!frameMs.empty())
  {
    // What a user waits for per mouse move (printed, never asserted).
    std::vector<double> t = frameMs, u = updateMs;
    std::sort(t.begin(), t.end());
    std::sort(u.begin(), u.end());
    std::printf("deformation frames: %zu; deformation median %.1f ms, slowest %.1f ms; with render median %.1f ms, "
                "slowest %.1f ms\n",
      t.size(), u[u.size() / 2], u.back(), t[t.size() / 2], t.back());
  }
  if (latticeFits + latticesReused > 0)
    std::printf("lattice fits: %zu (%zu kept from an earlier fit of the same piece)\n", latticeFits, latticesReused);
  if (scanRenderer->GetDraw())
    std::printf("view: %s\n", scanShown().c_str());
}

namespace
{
/// 'a', 'b', 'c'
std::string quotedList(const std::vector<std::string>& names)
{
  std::string text;
  for (std::size_t i = 0; i < names.size(); ++i)
    text += (i ? ", '" : "'") + names[i] + "'";
  return text;
}
} // namespace

std::string Planner::exportStructureSet(
  const std::string& folder, const std::vector<vtkSmartPointer<vtkPolyData>>& exported)
{
  exportNote.clear();
  exportedStructureSet = false;
  if (referenceImage.empty())
    return std::string();
  // An open piece (cut from a bone that is open where the scan ends) has no
  // closed contours to give.
  vtkNew<vtkLKStructureSetWriter> structureSet;
  std::vector<std::string> roiNames, leftOut;
  for (std::size_t p = 0; p < exported.size(); ++p)
  {
    const std::string given = pieceName(p);
    const std::string name =
      (given.empty() ? "piece " + std::to_string(p) : given) + (static_cast<int>(p) == movedPiece() ? " (moved)" : "");
    if (factsOf(p).openEdges > 0 || exported[p]->GetNumberOfPolys() == 0)
    {
      leftOut.push_back(name);
      continue;
    }
    structureSet->SetROIName(static_cast<int>(roiNames.size()), name.c_str());
    structureSet->AddInputData(exported[p]);
    roiNames.push_back(name);
  }
  if (roiNames.empty())
  {
    if (!leftOut.empty())
      exportNote = "none, every piece is open (" + quotedList(leftOut) +
        "); a bone that the scan's border cuts is closed with --close";
    return std::string();
  }
  // The mirror image shown, as the template the hospital's planning system
  // can show beside the pieces (closed, as the bone; a piece of that name
  // keeps it).
  const std::string mirrorName = "mirror image";
  if (session.mirror && mirror.surface && lkapp::pieceFacts(mirror.surface).openEdges == 0 &&
    std::find(roiNames.begin(), roiNames.end(), mirrorName) == roiNames.end())
  {
    structureSet->SetROIName(static_cast<int>(roiNames.size()), mirrorName.c_str());
    structureSet->AddInputData(mirror.surface);
    roiNames.push_back(mirrorName);
  }
  // The measurements' points as landmarks where the plan puts them (the
  // segment moved), named by what they measure.
  for (std::size_t i = 0; i < session.measurements.size(); ++i)
  {
    const Measurement& m = session.measurements[i];
    const Measurement shown = placed(m, session.segmentMatrix);
    const std::string what = "measurement " + std::to_string(i + 1) + ", " + measuredText(m) + ": ";
    // A point of the soft tissue (measured on the CT, not moved) says so.
    auto name = [&](const char* end, Measurement::End k) {
      return what + end + (m.pieces[k] == Measurement::kSoftTissue ? " (soft tissue)" : "");
    };
    if (m.angle)
    {
      structureSet->AddMarker(name("vertex", Measurement::AT).c_str(), shown.at[0], shown.at[1], shown.at[2]);
      structureSet->AddMarker(name("arm 1", Measurement::FROM).c_str(), shown.from[0], shown.from[1], shown.from[2]);
      structureSet->AddMarker(name("arm 2", Measurement::TO).c_str(), shown.to[0], shown.to[1], shown.to[2]);
    }
    else
    {
      structureSet->AddMarker(name("from", Measurement::FROM).c_str(), shown.from[0], shown.from[1], shown.from[2]);
      structureSet->AddMarker(name("to", Measurement::TO).c_str(), shown.to[0], shown.to[1], shown.to[2]);
    }
  }
  structureSet->SetReferenceFileName(referenceImage.c_str());
  structureSet->SetStructureSetLabel("latticekit plan");
  structureSet->SetFileName((folder + "/pieces.dcm").c_str());
  const int before = lkapp::errorCount();
  structureSet->Write();
  if (lkapp::errorCount() > before) // the CT moved away since it was read, say
  {
    exportNote = "not written: " + lkapp::errorsSince(before);
    return lkapp::errorsSince(before);
  }
  exportedStructureSet = true;
  exportNote = "pieces.dcm (RT structure set on the CT's slices): " + quotedList(roiNames) + ", " +
    std::to_string(structureSet->GetNumberOfContours()) + " contours";
  if (const int markers = structureSet->GetNumberOfMarkers())
    exportNote += ", " + std::to_string(markers) + " marker" + (markers == 1 ? "" : "s") + " (the measurements' points)";
  if (!leftOut.empty())
    exportNote += "; left out, open: " + quotedList(leftOut);
  return std::string();
}

namespace
{
/// "cut_line<number>_ct.png" or "cut_line<number>_across_ct.png", the
/// export's pictures of the CT on a cut line's plane and across it, and
/// "cut_line<number>[_across]_ct_<+-mm>mm.png", the view off that plane.
bool isScanPictureName(const std::string& name)
{
  static const std::regex picture("cut_line[0-9]+(_across)?_ct(_[-+][0-9.e+-]+mm)?[.]png");
  return std::regex_match(name, picture);
}
} // namespace

bool Planner::exportPieces(const std::string& folder, std::string& error)
{
  // The bone's own file among what the export writes or removes (a plan
  // made on an exported surface.vtp, exported into the same folder) would
  // be lost. A replayed session.json there is the plan's own, rewritten.
  if (lkapp::isExportedFile(input, folder,
        { "surface.vtp", "cut_lines.vtp", "plan.txt", "plan.png", "segment_transform.txt", "pieces.dcm", "mirror.stl",
          "mirror.vtp" }))
  {
    error = "the input '" + input + "' is one of the files the export writes or removes in '" + folder +
      "': export to another folder";
    return false;
  }
  if (const std::string name = vtksys::SystemTools::GetFilenameName(input);
      lkapp::isLatticeFileName(name) && lkapp::isExportedFile(input, folder, { name.c_str() }))
  {
    error = "the input '" + input + "' is a lattice file the export writes or removes in '" + folder +
      "': export to another folder";
    return false;
  }
  vtksys::SystemTools::MakeDirectory(folder);
  const std::string space = lkapp::coordinateSpace(bone); // "LPS" from an oriented CT; a mesh file's own tag
  std::vector<vtkSmartPointer<vtkPolyData>> exported; // as written: the segment where the plan moves it
  std::vector<std::string> stems;                     // the files' names: piece1, piece1-Strut_fragment
  std::vector<std::string> latticeFiles;              // lattice_piece1.vtp, ...
  for (std::size_t p = 0; p < pieces.size(); ++p)
  {
    // The segment goes where the plan moves it, and so does its lattice.
    const bool moved = static_cast<int>(p) == movedPiece() && !isIdentity(session.segmentMatrix);
    auto placed = [&](vtkPolyData* mesh) -> vtkSmartPointer<vtkPolyData> {
      if (!moved)
        return mesh;
      vtkNew<vtkTransform> t;
      t->SetMatrix(session.segmentMatrix.data());
      vtkNew<vtkTransformPolyDataFilter> move;
      move->SetInputData(mesh);
      move->SetTransform(t);
      move->Update();
      return move->GetOutput();
    };
    vtkSmartPointer<vtkPolyData> piece = placed(pieces[p]);
    stems.push_back(lkapp::pieceFileStem(p, pieceName(p)));
    for (const char* ext : lkapp::pieceExtensions)
    {
      const std::string path = folder + "/" + stems.back() + ext;
      if (!lkapp::writeMesh(piece, path, error, space))
        return false;
    }
    exported.push_back(piece);
    // The lattice shown (l), its kept lines as line cells: what
    // latticekit-lattice makes its smooth surface from.
    if (session.lattice && p < lattices.size() && lattices[p].lattice && lattices[p].surface &&
      lattices[p].surface->GetNumberOfPoints() > 0)
    {
      latticeFiles.push_back("lattice_" + stems.back() + ".vtp");
      if (!lkapp::writeMesh(placed(lattices[p].lattice), folder + "/" + latticeFiles.back(), error, space))
        return false;
    }
  }
  // A failure here is said at the end, after the plan and its session.
  const std::string structureSetError = exportStructureSet(folder, exported);
  // The surface the cut was made on (before deformations and the segment's
  // move) and the lines it was cut along.
  for (const auto& [mesh, name] : { std::make_pair(cut.surface, "surface.vtp"), std::make_pair(cut.loops, "cut_lines.vtp") })
    if (mesh && !lkapp::writeMesh(mesh, folder + "/" + name, error, space))
      return false;
  // The mirror image shown: a printed model of it is what a reconstruction
  // plate is bent on before the operation.
  const bool mirrorShown = session.mirror && mirror.surface;
  if (mirrorShown)
    for (const char* name : { "mirror.stl", "mirror.vtp" })
      if (!lkapp::writeMesh(mirror.surface, folder + "/" + name, error, space))
        return false;
  // The CT on each cut line's plane and across it, for the surgeon's notes.
  // A failure here is said at the end too.
  std::vector<std::string> scanPictures;
  std::string scanShownPicture, scanShownTitle, scanPicturesError;
  writeScanPictures(folder, scanPictures, scanShownPicture, scanShownTitle, scanPicturesError);
  // What the plan is, and the session that replays it beside the files.
  // Which scan, and which coordinates every position in the plan is in: a
  // plan file read later (or beside another patient's) must say so itself.
  // The batch report has said both already, at its start.
  std::string header;
  if (!input.empty())
    header += "input: " + input + "\n";
  if (!exportNote.empty())
    header += "structure set: " + exportNote + "\n";
  if (!scanPictures.empty())
  {
    header += std::string("the ") + (scanIsLabelMap ? "label map" : "CT") + " on and across the cut lines:";
    for (const auto& name : scanPictures)
      if (name != scanShownPicture)
        header += " " + name;
    header += "\n";
    if (!scanShownPicture.empty())
      header += "the view as shown: " + scanShownPicture + " (" + scanShownTitle + ")\n";
  }
  if (!latticeFiles.empty())
  {
    header += "the lattices shown, their kept lines as line cells:";
    for (const auto& name : latticeFiles)
      header += " " + name;
    header += "\n";
  }
  header += "coordinates: " +
    (space.empty() ? std::string("the input's own (its patient orientation is unknown)") : space + ", mm") + "\n";
  std::vector<std::pair<std::string, std::string>> texts{ { "plan.txt", header + planText() } };
  if (hasSegment())
    texts.emplace_back("segment_transform.txt", segmentText());
  for (const auto& [name, text] : texts)
    if (!lkapp::writeFileAtomically(folder + "/" + name, text, error))
      return false;
  if (!saveSession(session, folder + "/session.json", error))
    return false;
  // The plan as the window shows it, for the surgeon's notes and the
  // patient's file.
  if (!screenshot(folder + "/plan.png", error))
    return false;
  // An earlier export to the same folder can have left files this plan does
  // not make (more pieces, cut lines, a moved segment's transform): they go,
  // so that the folder holds this plan only.
  std::vector<std::string> others;
  if (!cut.surface)
    others.push_back("surface.vtp");
  if (!cut.loops)
    others.push_back("cut_lines.vtp");
  if (!hasSegment())
    others.push_back("segment_transform.txt");
  if (!exportedStructureSet) // an earlier plan's set is not this plan's
    others.push_back("pieces.dcm");
  if (!mirrorShown)
  {
    others.push_back("mirror.stl");
    others.push_back("mirror.vtp");
  }
  // The CT pictures of cut lines this plan does not have, and the lattices
  // it does not show.
  for (const auto& [isKind, written] : { std::make_pair(&isScanPictureName, &scanPictures),
         std::make_pair(&lkapp::isLatticeFileName, &latticeFiles) })
    for (const std::string& name : lkapp::filesNotWritten(folder, isKind, *written))
      others.push_back(name);
  if (!lkapp::removeStaleExports(folder, stems, others, error))
    return false;
  if (!scanPicturesError.empty())
  {
    error = scanPicturesError + " (the rest of the export was written)";
    return false;
  }
  if (!structureSetError.empty())
  {
    error = "the RT structure set '" + folder + "/pieces.dcm' was not written (the rest of the export was): " +
      structureSetError;
    return false;
  }
  return true;
}

bool Planner::screenshot(const std::string& path, std::string& error)
{
  return lkapp::writeScreenshot(window, path, error);
}

} // namespace lkplanner
