// latticekit-planner: the export (e, --export): the pieces, the lattices, the plan,
// its pictures, the session and, from a DICOM CT, the RT structure set; the screenshot.
#include "planner/Planner.h"
#include "planner/PlannerShared.h"

#include "common/AppSupport.h"
#include "common/AtomicFile.h"
#include "common/CutReport.h"

#include "vtkLKStructureSetWriter.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDataObject.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkMath.h>
#include <vtkProperty.h>
#include <vtkTextProperty.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtkMatrix4x4.h>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <regex>
#include <cstring>
#include <cstdlib>
#include <string>
#include <vector>

namespace lkplanner
{

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
  // The cutting guides shown, where the hospital's planning system shows
  // them on the CT beside the pieces.
  // A pair joined by a bar is one ROI, as it is one part.
  for (const GuidePart& part : guideParts())
  {
    if (session.guides && lkapp::pieceFacts(part.surface).openEdges == 0 &&
      std::find(roiNames.begin(), roiNames.end(), part.roiName) == roiNames.end())
    {
      structureSet->SetROIName(static_cast<int>(roiNames.size()), part.roiName.c_str());
      structureSet->AddInputData(part.surface);
      roiNames.push_back(part.roiName);
    }
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
      (lkapp::isLatticeFileName(name) || lkapp::isGuideFileName(name)) && lkapp::isInFolder(input, folder))
  {
    error = "the input '" + input + "' is a " + (lkapp::isGuideFileName(name) ? "cutting guide" : "lattice") +
      " file the export writes or removes in '" + folder + "': export to another folder";
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
  // The cutting guides shown, to print (STL) and to read back (VTP).
  // A pair joined by a bar is one part, in one file.
  std::vector<std::string> guideFiles;
  for (const GuidePart& part : guideParts())
    if (session.guides)
      for (const char* ext : { ".stl", ".vtp" })
      {
        guideFiles.push_back(part.stem + ext);
        if (!lkapp::writeMesh(part.surface, folder + "/" + guideFiles.back(), error, space))
          return false;
      }
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
  if (!guideFiles.empty())
  {
    header += "the cutting guides shown:";
    for (const auto& name : guideFiles)
      header += " " + name;
    header += "\n";
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
  // and guides it does not show.
  for (const auto& [isKind, written] : { std::make_pair(&isScanPictureName, &scanPictures),
         std::make_pair(&lkapp::isLatticeFileName, &latticeFiles), std::make_pair(&lkapp::isGuideFileName, &guideFiles) })
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
