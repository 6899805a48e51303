// latticekit-cut: a bone surface (or a fitted lattice) cut along closed lines
// into pieces (vtkLKClosedLineCutFilter), capped for printing by default.
#include "common/AppSupport.h"
#include "common/CutReport.h"
#include "common/GuidePairs.h"

#include "vtkLKClosedLineCutFilter.h"
#include "vtkLKCuttingGuideFilter.h"
#include "vtkLKGuideBarFilter.h"
#include "vtkLKExtractCutPieceFilter.h"
#include "vtkLKMeshPointIds.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPlaneCollection.h> // lkapp::planeCollection
#include <vtkPolyData.h>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <functional>
#include <iostream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace
{
void usage(std::ostream& os)
{
  os << "usage: latticekit-cut MESH -o CUT [options]\n"
        "\n"
        "Cuts a surface along closed lines into pieces (vtkLKClosedLineCutFilter): a bone surface\n"
        "(latticekit-surface) or a fitted lattice (latticekit-fit). By default each piece is closed\n"
        "by a cap (flat for a near-planar line, as a saw cut is), so it can be printed; on hollow\n"
        "bone the cut also takes the line's plane through the inner walls it meets.\n"
        "MESH: .vtp, .vtk, .stl, .ply or .obj, polygons; the lines are its line cells unless\n"
        "--lines gives them. CUT: every piece in one mesh, with cell data RegionId (the piece)\n"
        "and Cap (1 on cap triangles), point data InputPointId.\n"
        "\n"
        "  --lines LINES      the closed lines: polylines along edges of MESH whose points name\n"
        "                     MESH's points by point data MeshPointId or by equal coordinates\n"
        "                     (latticekit-demo writes mandible.vtp and cut_line.vtp so)\n"
        "  --open             no caps: the pieces keep open borders along the lines\n"
        "  --no-inner-walls   only the lines themselves are cut, never the inner walls\n"
        "  --pieces FOLDER    also write each piece as FOLDER/pieceN.stl, .vtp and .obj, and\n"
        "                     its cut lines as pieceN_cut_lines.vtp (MeshPointId naming\n"
        "                     pieceN.vtp's points: latticekit-fit pieceN.vtp --features\n"
        "                     pieceN_cut_lines.vtp --lock-features keeps them); files an\n"
        "                     earlier run left there beyond this cut's pieces are removed\n"
        "  --guides FOLDER    also write a cutting guide for each flat line (within 0.5 mm of\n"
        "                     its plane, as a saw line or a plane's section is) as\n"
        "                     FOLDER/guide_lineN.stl and .vtp (vtkLKCuttingGuideFilter on MESH:\n"
        "                     a shell on the bone's outer side with a slot in the line's plane,\n"
        "                     two screw holes and the line's number raised on it, both clear\n"
        "                     of the other flat lines' guides and saws); guide files an\n"
        "                     earlier run left there and this one does not write are removed\n"
        "  --join-guides      with --guides: the flat lines' guides joined, each line to the\n"
        "                     next either side of one piece (as they lie along the bone), by\n"
        "                     bars over the bone between them into one resection guide for\n"
        "                     each such chain of lines (vtkLKGuideBarFilter), written as\n"
        "                     FOLDER/guide_linesN-M.stl and .vtp (N-M-K for three, in their\n"
        "                     order) in place of the guides' own files\n"
        "  --guide-other-side N[,M...]\n"
        "                     with --guides: those lines' guides on the bone's other side (the\n"
        "                     inner, lingual one: the planner's K with the mouse on a guide)\n"
        "  -q, --quiet        no progress bar\n"
        "  -h, --help         this help\n";
}

/// The file --pieces writes for a piece's cut lines: "pieceN_cut_lines.vtp".
const std::string cutLinesSuffix = "_cut_lines.vtp";
bool isCutLinesFileName(const std::string& name)
{
  return name.size() > cutLinesSuffix.size() &&
    name.compare(name.size() - cutLinesSuffix.size(), cutLinesSuffix.size(), cutLinesSuffix) == 0 &&
    lkapp::isPieceFileName(name.substr(0, name.size() - cutLinesSuffix.size()) + ".vtp");
}

/// Makes `folder` for what `option` writes (`what`: "pieces", "guides") and
/// tries the file `probe` in it, so that a folder that cannot be written is
/// reported before the cut, not after it; first refuses an input among the
/// files written or removed there (`ours`). False with the message printed.
bool prepareFolder(const std::string& folder, const char* option, const char* what, const char* probe,
  const std::vector<std::string>& inputs, const std::function<bool(const std::string&)>& ours)
{
  for (const std::string& in : inputs)
    if (ours(in))
    {
      std::cerr << "error: '" << in << "' is one of the files " << option << " writes or removes in '" << folder
                << "': give the " << what << " another folder\n";
      return false;
    }
  std::string error;
  if (!vtksys::SystemTools::MakeDirectory(folder))
  {
    std::cerr << "error: cannot make the folder '" << folder << "' for the " << what << "\n";
    return false;
  }
  if (!lkapp::checkWritable(folder + "/" + probe, error))
  {
    std::cerr << "error: " << error << "\n";
    return false;
  }
  return true;
}

/// The files --guides writes: "guide_lineN.stl" and "guide_lineN.vtp"; with
/// --join-guides "guide_linesN-M.stl" and ".vtp" for those joined (N-M-K
/// for three, in their order along the bone).
bool isGuideLineFileName(const std::string& name)
{
  static const std::regex guide("guide_(line[0-9]+|lines[0-9]+(-[0-9]+)+)[.](stl|vtp)");
  return std::regex_match(name, guide);
}

/// A cutting guide for each line of `lines` (its line cells, in order,
/// numbered from 1) that lies within 0.5 mm of its best-fitting plane, on
/// `mesh`, written into `folder`, on the bone's other side for the lines
/// numbered in `otherSide` (from 1); a line per guide on standard output. With
/// `join`, those lines' guides joined along the bone, each line to the next
/// across one of the cut's `pieces` (lkapp::chainLinesByPiece), by bars into
/// one part for each chain (vtkLKGuideBarFilter), written in place of the
/// guides' own files. False with `error` when a file cannot be written.
bool writeGuides(vtkPolyData* mesh, vtkPolyData* lines, const std::string& folder, const std::string& space,
  bool join, const std::set<std::size_t>& otherSide, const std::vector<vtkPolyData*>& pieces,
  std::vector<std::string>& written, std::string& error)
{
  const std::vector<lkapp::LineFacts> facts = lkapp::lineFacts(lines);
  vtkNew<vtkPolyData> faces; // the bone, without its line cells
  faces->SetPoints(mesh->GetPoints());
  faces->SetPolys(mesh->GetPolys());
  faces->SetStrips(mesh->GetStrips());
  faces->GetFieldData()->PassData(mesh->GetFieldData());
  // The guide of each flat line (or why there is none), in the lines' order.
  struct Guide
  {
    std::size_t line = 0; // from 0
    std::vector<std::array<double, 3>> points; // the line's, for its chain
    vtkSmartPointer<vtkLKCuttingGuideFilter> filter;
    std::string why;         // empty when it was made
    std::string joinedStem;  // the part it is in, when joined
  };
  std::vector<Guide> guides;
  std::vector<std::string> report(facts.size());
  auto labelOf = [](std::size_t line) { return "guide line " + std::to_string(line + 1); };
  // Each flat line's plane (origin, normal) and points: the plane through
  // the line's first point, moved onto its best plane, so that the guide
  // goes on the part of the bone the line runs round (not on an inner wall
  // nearer the line's centre).
  struct Flat
  {
    std::array<double, 6> plane{};
    std::vector<std::array<double, 3>> points;
  };
  std::map<std::size_t, Flat> flats;
  {
    auto it = vtk::TakeSmartPointer(lines->GetLines()->NewIterator());
    std::size_t k = 0;
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal() && k < facts.size(); it->GoToNextCell(), ++k)
    {
      const lkapp::LineFacts& f = facts[k];
      if (!f.closed || f.flatness > 0.5)
        continue;
      vtkIdType n = 0;
      const vtkIdType* ids = nullptr;
      it->GetCurrentCell(n, ids);
      Flat flat;
      double* origin = flat.plane.data();
      lines->GetPoint(ids[0], origin);
      double apart[3];
      vtkMath::Subtract(origin, f.centre, apart);
      const double off = vtkMath::Dot(apart, f.normal);
      for (int c = 0; c < 3; ++c)
      {
        origin[c] -= off * f.normal[c];
        flat.plane[3 + c] = f.normal[c];
      }
      for (vtkIdType i = 0; i < n; ++i)
      {
        double x[3];
        lines->GetPoint(ids[i], x);
        flat.points.push_back({ x[0], x[1], x[2] });
      }
      flats[k] = flat;
    }
  }
  for (std::size_t k = 0; k < facts.size(); ++k)
  {
    const lkapp::LineFacts& f = facts[k];
    if (!f.closed || f.flatness > 0.5)
    {
      char why[80] = "is not closed";
      if (f.closed)
        std::snprintf(why, sizeof why, "is %.2f mm off its plane", f.flatness);
      char line[200];
      std::snprintf(line, sizeof line, "%-16s none: the line %s (a saw cuts a plane)\n", labelOf(k).c_str(), why);
      report[k] = line;
      continue;
    }
    const Flat& flat = flats.at(k);
    Guide g;
    g.line = k;
    g.points = flat.points;
    g.filter = vtkSmartPointer<vtkLKCuttingGuideFilter>::New();
    g.filter->SetInputData(faces);
    g.filter->SetPlaneOrigin(flat.plane.data());
    g.filter->SetPlaneNormal(flat.plane.data() + 3);
    g.filter->SetLabel(std::to_string(k + 1).c_str()); // the line's number, as its file name gives it
    // The other flat lines' planes: the label and screw holes keep clear of
    // their guides and saws (the filter passes over those far away).
    std::vector<std::array<double, 6>> others;
    for (const auto& [j, other] : flats)
      if (j != k)
        others.push_back(other.plane);
    g.filter->SetOtherCutPlanes(lkapp::planeCollection(others));
    g.filter->SetOtherSide(otherSide.count(k + 1) > 0);
    // The cut stands without a guide: why one is not made is this line's
    // report, not an error of the run.
    g.why = lkapp::updateKeepingErrors(g.filter);
    if (g.filter->GetOutput()->GetNumberOfPolys() == 0 && g.why.empty())
      g.why = "no guide was made";
    else if (g.filter->GetOutput()->GetNumberOfPolys() > 0)
      g.why.clear();
    guides.push_back(g);
  }
  // The joined guides, after the lines' own reports.
  std::string joinedReport;
  auto write = [&](vtkPolyData* part, const std::string& stem) {
    for (const char* ext : { ".stl", ".vtp" })
    {
      written.push_back(stem + ext);
      if (!lkapp::writeMesh(part, folder + "/" + written.back(), error, space))
        return false;
    }
    return true;
  };
  // The chains: flat lines either side of each piece (the segment between
  // two saw cuts), as they lie along the bone.
  std::vector<std::vector<std::array<double, 3>>> guideLines;
  for (const Guide& g : guides)
    guideLines.push_back(g.points);
  const std::vector<std::set<std::size_t>> piecesOf =
    lkapp::piecesAlongLines(pieces, guideLines, 1e-5 * mesh->GetLength());
  const std::vector<std::vector<std::size_t>> chains =
    join ? lkapp::chainLinesByPiece(piecesOf) : std::vector<std::vector<std::size_t>>();
  auto lineNumber = [&](std::size_t g) { return std::to_string(guides[g].line + 1); };
  // Each chain joined, or as much of it as can be (lkapp::joinChain).
  std::map<std::vector<std::size_t>, vtkSmartPointer<vtkLKGuideBarFilter>> parts;
  auto joinLines = [&](const std::vector<std::size_t>& members) {
    auto bar = vtkSmartPointer<vtkLKGuideBarFilter>::New();
    bar->SetBoneData(faces);
    for (std::size_t g : members)
      bar->AddGuideData(guides[g].filter->GetOutput());
    const std::string why = lkapp::updateKeepingErrors(bar);
    parts[members] = bar;
    return bar->GetOutput()->GetNumberOfPolys() > 0 ? std::string()
      : why.empty()                                  ? "no bar was made"
                                                     : lkapp::guidesByLine(why, members, "line", lineNumber);
  };
  for (const auto& chain : chains)
  {
    char line[600];
    for (std::size_t g : chain)
      if (!guides[g].why.empty())
        joinedReport += labelOf(guides[g].line) + " is left out of the resection guide: it has no guide\n";
    for (const lkapp::JoinedRun& run :
      lkapp::joinChain(chain, [&](std::size_t g) { return guides[g].why.empty(); }, joinLines))
    {
      const std::string label = "guide lines " + lkapp::chainNumbers(run.lines, lineNumber, "-", "-");
      if (!run.error.empty())
      {
        std::snprintf(line, sizeof line, "%-16s not joined%s: %s\n", label.c_str(),
          run.lines.size() > 2 ? " in one part" : "", run.error.c_str());
        joinedReport += line;
        continue;
      }
      vtkLKGuideBarFilter* bar = parts[run.lines];
      const std::string stem = "guide_lines" + lkapp::chainNumbers(run.lines, lineNumber, "-", "-");
      if (!write(bar->GetOutput(), stem))
        return false;
      for (std::size_t g : run.lines)
        guides[g].joinedStem = stem;
      std::snprintf(line, sizeof line, "%-16s %s; put on %s; %.0f mm^3 in one part: %s.stl, .vtp\n", label.c_str(),
        lkapp::joinText(bar, run.lines, "line", lineNumber).c_str(), lkapp::insertionText(bar).c_str(), bar->GetVolume(),
        stem.c_str());
      joinedReport += line;
    }
  }
  for (std::size_t i = 0; join && i < guides.size(); ++i)
    if (const std::string why = lkapp::whyLineStaysApart(i, piecesOf, chains, "flat line", "line", lineNumber);
        !why.empty())
      joinedReport += labelOf(guides[i].line) + " stays apart: " + why + "\n";
  for (const Guide& g : guides)
  {
    char line[600];
    if (!g.why.empty())
      std::snprintf(line, sizeof line, "%-16s none: %s\n", labelOf(g.line).c_str(), g.why.c_str());
    else
    {
      const std::string stem = g.joinedStem.empty() ? "guide_line" + std::to_string(g.line + 1) : g.joinedStem;
      if (g.joinedStem.empty() && !write(g.filter->GetOutput(), stem))
        return false;
      vtkLKCuttingGuideFilter* guide = g.filter;
      const std::array<double, 3> along = lkapp::guideDirection(guide->GetApproachUsed());
      std::snprintf(line, sizeof line,
        "%-16s slot %.1f mm long and %.1f mm wide, walls %.1f mm thick, %d screw hole(s) of %.1f mm%s, on "
        "%.0f mm^2 of bone, put on along (%.3f, %.3f, %.3f); %.0f mm^3: %s%s.stl%s\n",
        labelOf(g.line).c_str(), guide->GetSlotLength(), guide->GetSlotWidth(), guide->GetThickness(),
        guide->GetNumberOfScrewHoles(), guide->GetScrewHoleDiameter(),
        guide->GetLabelPlaced() ? (", labelled \"" + std::string(guide->GetLabel()) + "\"").c_str() : "",
        guide->GetContactArea(), along[0], along[1],
        along[2], guide->GetVolume(), g.joinedStem.empty() ? "" : "in ", stem.c_str(),
        g.joinedStem.empty() ? ", .vtp" : "");
    }
    report[g.line] = line;
  }
  for (const std::string& line : report)
    std::fputs(line.c_str(), stdout);
  std::fputs(joinedReport.c_str(), stdout);
  // Guides on lines nearer than their reaches cannot be on the bone together.
  std::vector<vtkPolyData*> made;
  for (const Guide& g : guides)
    made.push_back(g.why.empty() ? g.filter->GetOutput() : nullptr);
  for (const lkapp::GuideOverlap& o : lkapp::overlappingGuides(made))
    if (guides[o.first].joinedStem.empty() || guides[o.first].joinedStem != guides[o.second].joinedStem)
      std::printf("guide lines %zu and %zu overlap over %.1f mm along the bone: they cannot be on it together%s\n",
        guides[o.first].line + 1, guides[o.second].line + 1, o.along,
        join ? "" : " (--join-guides merges them into one block with both slots)");
  return true;
}

} // namespace

int main(int argc, char* argv[])
{
  lkapp::installCrashReport("latticekit-cut");
  std::string input, output, linesPath, piecesFolder, guidesFolder;
  bool quiet = false, capping = true, innerWalls = true, joinGuides = false;
  std::set<std::size_t> otherSide; // lines (from 1) whose guides go on the bone's other side
  std::string otherSideText;
  lkapp::Arguments args(argc, argv, usage);
  std::string a;
  while (args.next(a))
  {
    if (a == "-o" || a == "--output")
      output = args.value(a);
    else if (a == "--lines")
      linesPath = args.value(a);
    else if (a == "--open")
      capping = false;
    else if (a == "--no-inner-walls")
      innerWalls = false;
    else if (a == "--pieces")
      piecesFolder = args.value(a);
    else if (a == "--guides")
      guidesFolder = args.value(a);
    else if (a == "--join-guides")
      joinGuides = true;
    else if (a == "--guide-other-side")
      otherSideText = args.value(a);
    else if (a == "-q" || a == "--quiet")
      quiet = true;
    else if (lkapp::Arguments::isOption(a))
      args.unknown(a);
    else
      args.positional(a, input, "mesh");
  }
  if (input.empty() || output.empty())
  {
    std::cerr << "error: a MESH and -o CUT are required\n";
    usage(std::cerr);
    return 2;
  }
  if (joinGuides && guidesFolder.empty())
  {
    std::cerr << "error: --join-guides joins the guides --guides FOLDER makes: give --guides too\n";
    return 2;
  }
  if (!otherSideText.empty())
  {
    if (guidesFolder.empty())
    {
      std::cerr << "error: --guide-other-side turns guides --guides FOLDER makes: give --guides too\n";
      return 2;
    }
    static const std::regex numbers("[1-9][0-9]{0,8}(,[1-9][0-9]{0,8})*");
    if (!std::regex_match(otherSideText, numbers))
    {
      std::cerr << "error: --guide-other-side takes line numbers from 1, with commas between (1,3), not '"
                << otherSideText << "'\n";
      return 2;
    }
    std::stringstream list(otherSideText);
    for (std::string number; std::getline(list, number, ',');)
      otherSide.insert(static_cast<std::size_t>(std::stoul(number)));
  }
  lkapp::installMessageHandler(quiet);
  if (!lkapp::checkAllWritable({ output }, { input, linesPath }))
    return 1;
  // The pieces' files (pieceN.stl, .vtp, .obj) are written there, and
  // those of an earlier cut beyond this one's count removed: an input among
  // them (a piece cut again into its own folder) would be lost. So for the
  // guides' files.
  if (!piecesFolder.empty() &&
    !prepareFolder(piecesFolder, "--pieces", "pieces", "piece0.stl", { input, linesPath },
      [&](const std::string& in) {
        return lkapp::isExportedFile(in, piecesFolder, {}) ||
          (isCutLinesFileName(vtksys::SystemTools::GetFilenameName(in)) && lkapp::isInFolder(in, piecesFolder));
      }))
    return 1;
  if (!guidesFolder.empty() &&
    !prepareFolder(guidesFolder, "--guides", "guides", "guide_line1.stl", { input, linesPath },
      [&](const std::string& in) {
        return isGuideLineFileName(vtksys::SystemTools::GetFilenameName(in)) && lkapp::isInFolder(in, guidesFolder);
      }))
    return 1;
  std::string error;
  vtkSmartPointer<vtkPolyData> mesh = lkapp::readMesh(input, error);
  vtkSmartPointer<vtkPolyData> lines;
  if (mesh && !linesPath.empty())
    lines = lkapp::readMesh(linesPath, error);
  if (!mesh || (!linesPath.empty() && !lines))
  {
    std::cerr << "error: " << error << "\n";
    return 1;
  }
  if (const std::string off = lkvtk::linesOffTheirMeshPoints(lines, mesh); !off.empty())
  {
    // Ids that happen to be edges of this mesh would cut along a line nobody drew.
    std::cerr << "error: '" << linesPath << "' does not fit '" << input << "': " << off
              << ": the lines were made on another mesh (the planner's cut_lines.vtp names its surface.vtp, the main "
                 "job's cut_line.vtp its mandible.vtp)\n";
    return 1;
  }
  if (linesPath.empty() && mesh->GetNumberOfLines() == 0)
  {
    std::cerr << "error: '" << input
              << "' has no line cells to cut along: give the closed lines with --lines LINES\n";
    return 1;
  }
  if (const vtkIdType count = (lines ? lines.Get() : mesh.Get())->GetNumberOfLines();
      !otherSide.empty() && static_cast<vtkIdType>(*otherSide.rbegin()) > count)
  {
    std::cerr << "error: --guide-other-side names line " << *otherSide.rbegin() << ", but there "
              << (count == 1 ? "is 1 line" : "are " + std::to_string(count) + " lines") << "\n";
    return 2;
  }

  const auto start = std::chrono::steady_clock::now();
  vtkNew<vtkLKClosedLineCutFilter> cut;
  cut->SetInputData(mesh);
  if (lines)
    cut->SetLinesData(lines);
  cut->SetCapping(capping);
  cut->SetCutInnerWalls(innerWalls);
  {
    lkapp::ProgressBar bar(cut, "cut", !quiet);
    cut->Update();
  }
  if (lkapp::errorCount() > 0)
    return 1;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const std::string space = lkapp::coordinateSpace(mesh); // the input's, for every file written
  if (!lkapp::writeMesh(cut->GetOutput(), output, error, space))
  {
    std::cerr << "error: " << error << "\n";
    return 1;
  }
  std::printf("input            %lld points, %lld faces; %s\n", static_cast<long long>(mesh->GetNumberOfPoints()),
    static_cast<long long>(mesh->GetNumberOfPolys()),
    lines ? ("lines from " + linesPath).c_str() : "its own line cells");
  std::printf("cut              %d %s, %s%s, %.3f s\n", cut->GetNumberOfPieces(),
    cut->GetNumberOfPieces() == 1 ? "piece" : "pieces", capping ? "capped" : "open",
    cut->GetNumberOfInnerWallLines() > 0
      ? (", also through the inner walls (" + std::to_string(cut->GetNumberOfInnerWallLines()) + " lines)").c_str()
      : "",
    seconds);
  std::printf("%s",
    lkapp::lineFactsText(lkapp::lineFacts(lines ? lines.Get() : mesh.Get()), space == "LPS")
      .c_str());
  std::vector<std::string> pieceStems; // the files' names, piece0, piece1, ...
  std::vector<std::string> cutLinesFiles; // piece0_cut_lines.vtp, ...
  std::vector<vtkSmartPointer<vtkPolyData>> pieces; // for joining the guides along the bone
  vtkNew<vtkLKExtractCutPieceFilter> extract;
  extract->SetInputConnection(cut->GetOutputPort());
  for (int p = 0; p < cut->GetNumberOfPieces(); ++p)
  {
    extract->SetPiece(p);
    extract->Update();
    vtkNew<vtkPolyData> piece;
    piece->ShallowCopy(extract->GetOutput());
    pieces.push_back(piece);
    const lkapp::PieceFacts facts = lkapp::pieceFacts(piece);
    std::printf("piece %-11d %lld points, %lld faces (%lld cap)%s\n", p,
      static_cast<long long>(piece->GetNumberOfPoints()), static_cast<long long>(facts.faces),
      static_cast<long long>(facts.capFaces), lkapp::pieceFactsText(facts).c_str());
    if (piecesFolder.empty())
      continue;
    pieceStems.push_back(lkapp::pieceFileStem(static_cast<std::size_t>(p)));
    // For STL and OBJ the piece alone, without the cut's arrays.
    vtkNew<vtkPolyData> plain;
    plain->ShallowCopy(piece);
    plain->GetPointData()->Initialize();
    plain->GetCellData()->Initialize();
    for (const char* ext : lkapp::pieceExtensions)
      if (!lkapp::writeMesh(ext == std::string(".vtp") ? piece.Get() : plain.Get(),
            piecesFolder + "/" + pieceStems.back() + ext, error, space))
      {
        std::cerr << "error: " << error << "\n";
        return 1;
      }
    cutLinesFiles.push_back(pieceStems.back() + cutLinesSuffix);
    if (!lkapp::writeMesh(extract->GetCutLinesOutput(), piecesFolder + "/" + cutLinesFiles.back(), error, space))
    {
      std::cerr << "error: " << error << "\n";
      return 1;
    }
  }
  // The cut lines of pieces this cut does not make go with their pieces.
  if (!piecesFolder.empty() &&
    !lkapp::removeStaleExports(
      piecesFolder, pieceStems, lkapp::filesNotWritten(piecesFolder, isCutLinesFileName, cutLinesFiles), error))
  {
    std::cerr << "error: " << error << "\n";
    return 1;
  }
  if (!guidesFolder.empty())
  {
    std::vector<std::string> guideFiles;
    std::vector<vtkPolyData*> piecesMade;
    for (const auto& piece : pieces)
      piecesMade.push_back(piece);
    if (!writeGuides(
          mesh, lines ? lines.Get() : mesh.Get(), guidesFolder, space, joinGuides, otherSide, piecesMade, guideFiles,
          error))
    {
      std::cerr << "error: " << error << "\n";
      return 1;
    }
    // An earlier run's guides that this one does not write go.
    for (const std::string& name : lkapp::filesNotWritten(guidesFolder, isGuideLineFileName, guideFiles))
      if (!vtksys::SystemTools::RemoveFile(guidesFolder + "/" + name))
      {
        std::cerr << "error: cannot remove the earlier guide '" << guidesFolder << "/" << name << "'\n";
        return 1;
      }
  }
  std::printf("written          %s (%lld bytes)%s%s\n", output.c_str(), lkapp::fileBytes(output),
    piecesFolder.empty() ? "" : (", and the pieces in " + piecesFolder).c_str(),
    guidesFolder.empty() ? "" : (", and the guides in " + guidesFolder).c_str());
  return 0;
}
