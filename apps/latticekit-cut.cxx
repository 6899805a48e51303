// latticekit-cut: a bone surface (or a fitted lattice) cut along closed lines
// into pieces (vtkLKClosedLineCutFilter), capped for printing by default.
#include "common/AppSupport.h"
#include "common/CutReport.h"

#include "vtkLKClosedLineCutFilter.h"
#include "vtkLKExtractCutPieceFilter.h"
#include "vtkLKMeshPointIds.h"

#include <vtkCellData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtksys/SystemTools.hxx>

#include <chrono>
#include <cstdio>
#include <iostream>
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

} // namespace

int main(int argc, char* argv[])
{
  lkapp::installCrashReport("latticekit-cut");
  std::string input, output, linesPath, piecesFolder;
  bool quiet = false, capping = true, innerWalls = true;
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
  lkapp::installMessageHandler(quiet);
  if (!lkapp::checkAllWritable({ output }, { input, linesPath }))
    return 1;
  if (!piecesFolder.empty())
  {
    // The pieces' files (pieceN.stl, .vtp, .obj) are written there, and
    // those of an earlier cut beyond this one's count removed: an input
    // among them (a piece cut again into its own folder) would be lost.
    for (const std::string& in : { input, linesPath })
    {
      if (lkapp::isExportedFile(in, piecesFolder, {}) ||
        (isCutLinesFileName(vtksys::SystemTools::GetFilenameName(in)) && lkapp::isInFolder(in, piecesFolder)))
      {
        std::cerr << "error: '" << in << "' is one of the files --pieces writes or removes in '" << piecesFolder
                  << "': give the pieces another folder\n";
        return 1;
      }
    }
    // The folder is made now, and a file in it tried, so that a folder that
    // cannot be written is reported before the cut, not after it.
    std::string error;
    if (!vtksys::SystemTools::MakeDirectory(piecesFolder))
    {
      std::cerr << "error: cannot make the folder '" << piecesFolder << "' for the pieces\n";
      return 1;
    }
    if (!lkapp::checkWritable(piecesFolder + "/piece0.stl", error))
    {
      std::cerr << "error: " << error << "\n";
      return 1;
    }
  }
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
  vtkNew<vtkLKExtractCutPieceFilter> extract;
  extract->SetInputConnection(cut->GetOutputPort());
  for (int p = 0; p < cut->GetNumberOfPieces(); ++p)
  {
    extract->SetPiece(p);
    extract->Update();
    vtkNew<vtkPolyData> piece;
    piece->ShallowCopy(extract->GetOutput());
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
  std::printf("written          %s (%lld bytes)%s\n", output.c_str(), lkapp::fileBytes(output),
    piecesFolder.empty() ? "" : (", and the pieces in " + piecesFolder).c_str());
  return 0;
}
