// latticekit-planner: the osteotomy planner in a plain VTK render window.
// Draw strokes on the bone, turn them into feature lines, cut along closed
// lines, fit lattices to the pieces, see the Metro error, undo and redo,
// deform the pieces (bump, box, smoothing brush on adaptively refined
// patches), save and replay sessions (JSON), export the pieces.
#include "common/AppSupport.h"
#include "planner/PlannerSession.h"
#include "planner/PlannerStyle.h"

#include "vtkLKBoneSurfaceFilter.h"
#include "vtkLKMedicalImageReader.h"
#include "vtkLKMeshRepairFilter.h"

#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkRenderWindowInteractor.h>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <cstring>
#include <string>
#include <vector>

#include <unistd.h>

namespace
{
using namespace lkplanner;

void usage(std::ostream& os)
{
  os << "usage: latticekit-planner INPUT [options]\n"
        "\n"
        "The osteotomy planner: a VTK window on the bone surface of INPUT (a CT or label map:\n"
        "DICOM folder or file (a DICOM SEG, an RT structure set), .nrrd, .mha, .nii; or a mesh:\n"
        ".vtp .vtk .stl .ply .obj).\n"
        "Keys: "
     << kHelp
     << "\n"
        "The CT view (c): drag on it for its window (right: wider, up: brighter; C: the presets),\n"
        "the wheel over it moves its plane 1 mm a step, and while measuring (u, a) a click on it\n"
        "picks a point of its plane (the canal's, a root's); a point of the soft tissue, more\n"
        "than 3 mm outside the bone, stays where it is when the segment moves.\n"
        "Delete (or BackSpace) with the mouse on a stroke's or a measurement's line removes it\n"
        "(a stroke that made no line: where it was drawn, dark red),\n"
        "and elsewhere on the bone the deformation there (the latest; a smoothing brush stroke\n"
        "whole), the others kept (z brings it back); while measuring it takes back the last\n"
        "point clicked.\n"
        "Each piece's lattice (l) keeps its cut lines and the strokes' lines on it as lattice\n"
        "edges; L and a number set its vertices per piece (600 by default, at least twice the\n"
        "lines' vertices); the export writes the lattices shown as lattice_pieceN.vtp.\n"
        "\n"
        "  --iso V              a CT's bone threshold (default 300 HU; a 0/1 label map is found\n"
        "                       and taken at 0.5)\n"
        "  --seed X,Y,Z         keep the bone component nearest this patient-space point (mm)\n"
        "                       instead of the largest (the mandible, where the skull is larger)\n"
        "  --crop X0,X1,Y0,Y1,Z0,Z1\n"
        "                       only the CT inside this patient-space box (mm), padded with air\n"
        "                       so that the surface closes where the box cuts bone\n"
        "  --close              close the surface where the scan's border cuts bone (padded with\n"
        "                       air as a crop is; a skull vault above the last slice): an open\n"
        "                       surface is cut in two only by a line all round its open part\n"
        "  --label N|NAME       one label of a label map with several (a segmentation: its\n"
        "                       voxels of value N), or by name a segment of a segmentation\n"
        "                       (.seg.nrrd, DICOM SEG) or an ROI of an RT structure set\n"
        "  --series I           DICOM: series I of the folder (0 = largest, the default)\n"
        "  --smooth N           windowed-sinc smoothing of the surface, N iterations (default 20\n"
        "                       for a 0/1 label map, which takes its slice staircase out, none\n"
        "                       for a CT; each iteration moves the surface a little)\n"
        "  --image-smooth S     Gaussian smoothing of the volume before its surface, standard\n"
        "                       deviation in voxels, 0 to 20 (default 0.5 for a 0/1 label map,\n"
        "                       none for a CT). With 20 iterations this followed label maps of\n"
        "                       known shapes most closely; one voxel (the default before\n"
        "                       December 2026; a session saved then keeps it) wears thin\n"
        "                       processes down across 2.5 mm slices (a coronoid's tip by 3 to 6 mm)\n"
        "  --head X,Y,Z --front X,Y,Z\n"
        "                       for a scan whose file gives no orientation (a NIfTI without qform\n"
        "                       or sform): where the patient's head and face point in its\n"
        "                       coordinates; the CT view stands head up, the first view is from\n"
        "                       the front (the bundled head: --head 0,0,-1 --front 0,-1,0)\n"
        "  --replay SESSION     apply a saved session (JSON: strokes, cut, lattice, metro, moved segment,\n"
        "                       deformations)\n"
        "  --screenshot PNG     render once to PNG and exit (no window needed: use xvfb-run)\n"
        "  --export FOLDER      write every piece as STL, VTP and OBJ, the surface the cut was made\n"
        "                       on (surface.vtp), the lines it took (cut_lines.vtp, for\n"
        "                       latticekit-cut --lines), the plan (plan.txt: the input, the\n"
        "                       coordinates, pieces, volumes, cut lines and planes), a picture\n"
        "                       of it (plan.png), the session that replays it (session.json),\n"
        "                       from a CT the CT on each cut line's plane (cut_line1_ct.png, ...;\n"
        "                       the view as shown, off that plane: cut_line1_ct_+3mm.png)\n"
        "                       and, from a DICOM CT, the closed pieces as an RT structure set\n"
        "                       on the CT's slices (pieces.dcm), and exit\n"
        "  --session OUT        where 'w' saves the session (default planner_session.json);\n"
        "                       changes not saved are kept after every step in OUT's name with\n"
        "                       -unsaved (planner_session-unsaved.json)\n"
        "  --events LOG         play an event stream (vtkInteractorEventRecorder's format: mouse\n"
        "                       strokes, keys) through the window, then report (and\n"
        "                       --screenshot, --export) and exit\n"
        "  -h, --help           this help\n";
}

/// At quitting: a session changed since it was last replayed, saved or
/// exported is kept beside the session file (Planner::keepUnsaved, which
/// also runs after every step), so that closing the window (or an Escape
/// meant for something else) loses no plan; says where. False if it cannot
/// be written.
bool keepUnsavedSession(Planner& planner)
{
  std::string error;
  if (!planner.keepUnsaved(error))
  {
    std::cerr << "error: the session had changes that were not saved, and they could not be kept (--session sets where): " << error << "\n";
    return false;
  }
  if (planner.keptSession.empty())
    return true; // nothing differs from the saved session
  const std::string& path = planner.unsavedPath;
  std::cout << "unsaved: the session had changes that were not saved ('w' saves them); they are kept in " << path
            << ": open them again with --replay " << path << "\n";
  return true;
}
} // namespace

int main(int argc, char* argv[])
{
  lkapp::installCrashReport("latticekit-planner");
  std::string input, replay, shot, exportFolder, events, sessionOut = "planner_session.json";
  double iso = 300.0, seed[3] = { 0, 0, 0 }, crop[6] = { 0, 0, 0, 0, 0, 0 };
  bool isoGiven = false, seeded = false, cropped = false, closed = false;
  long series = -1, smoothing = -1, label = 0;
  double imageSmoothing = -1.0;
  std::string labelName;
  double head[3] = { 0, 0, 0 }, front[3] = { 0, 0, 0 };
  bool headGiven = false, frontGiven = false;
  lkapp::Arguments args(argc, argv, usage);
  std::string a;
  while (args.next(a))
  {
    if (a == "--iso")
    {
      iso = args.number(a, -std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), "a number");
      isoGiven = true;
    }
    else if (a == "--seed")
    {
      args.triple(a, seed);
      seeded = true;
    }
    else if (a == "--crop")
    {
      args.box(a, crop);
      cropped = true;
    }
    else if (a == "--close")
      closed = true;
    else if (a == "--series")
      series = args.integer(a, 0, std::numeric_limits<int>::max(), "an integer >= 0");
    else if (a == "--smooth")
      smoothing = args.integer(a, 0, 1000, "an integer from 0 to 1000");
    else if (a == "--image-smooth")
      imageSmoothing = args.number(a, 0.0, 20.0, "a number from 0 to 20");
    else if (a == "--label")
      args.labelOrName(a, label, labelName);
    else if (a == "--head")
    {
      args.triple(a, head);
      headGiven = true;
    }
    else if (a == "--front")
    {
      args.triple(a, front);
      frontGiven = true;
    }
    else if (a == "--replay")
      replay = args.value(a);
    else if (a == "--screenshot")
      shot = args.value(a);
    else if (a == "--export")
      exportFolder = args.value(a);
    else if (a == "--events")
      events = args.value(a);
    else if (a == "--session")
      sessionOut = args.value(a);
    else if (lkapp::Arguments::isOption(a))
      args.unknown(a);
    else
      args.positional(a, input, "input");
  }
  if (input.empty())
  {
    std::cerr << "error: an INPUT is required\n";
    usage(std::cerr);
    return 2;
  }
  if (headGiven != frontGiven)
  {
    std::cerr << "error: --head and --front go together: where the patient's head and face point in the scan's "
                 "coordinates\n";
    return 2;
  }
  const lkapp::HeadAndFront patient{ { head[0], head[1], head[2] }, { front[0], front[1], front[2] } };
  if (headGiven && !lkapp::isValid(patient))
  {
    std::cerr << "error: --head and --front must be non-zero and not parallel (10 degrees apart at least)\n";
    return 2;
  }
  lkapp::installMessageHandler(true);
  Planner planner;
  std::string error;
  const std::string ext = vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(input));
  std::string ignoredFields;
  if (!replay.empty() && !loadSession(replay, planner.session, error, &ignoredFields))
  {
    std::cerr << "error: " << error << "\n";
    return 1;
  }
  // The surface: a mesh file through the same repair as the CT's surface
  // gets (polygons triangulated, a triangle soup such as an STL from
  // elsewhere merged, non-manifold vertices split, the orientation made
  // consistent; split mode, the cut and the lattice need that, and refused
  // such a mesh one step at a time without it), or a volume's bone surface.
  vtkNew<vtkLKMeshRepairFilter> repair;
  vtkNew<vtkLKMedicalImageReader> reader;
  vtkNew<vtkLKBoneSurfaceFilter> bone;
  vtkSmartPointer<vtkPolyData> mesh;
  vtkPolyDataAlgorithm* surface = bone;
  if (ext == ".vtp" || ext == ".vtk" || ext == ".stl" || ext == ".ply" || ext == ".obj")
  {
    // The options given that only a scan has use for, named.
    std::vector<std::string> given;
    for (const auto& [on, name] : { std::make_pair(isoGiven, "--iso"), std::make_pair(seeded, "--seed"),
           std::make_pair(cropped, "--crop"), std::make_pair(closed, "--close"), std::make_pair(series >= 0, "--series"),
           std::make_pair(smoothing >= 0, "--smooth"), std::make_pair(imageSmoothing >= 0.0, "--image-smooth"),
           std::make_pair(label > 0 || !labelName.empty(), "--label"),
           std::make_pair(headGiven, "--head"), std::make_pair(frontGiven, "--front") })
      if (on)
        given.emplace_back(name);
    if (!given.empty())
    {
      std::string names;
      for (std::size_t k = 0; k < given.size(); ++k)
        names += (k == 0 ? "" : k + 1 == given.size() ? " and " : ", ") + given[k];
      std::cerr << "error: " << names << (given.size() == 1 ? " is" : " are") << " for a CT or label map (--iso, --seed, "
                << "--crop, --close, --series, --smooth, --image-smooth, --label, --head, --front); '" << input
                << "' is a mesh\n";
      return 2;
    }
    mesh = lkapp::readMesh(input, error);
    if (!mesh)
    {
      std::cerr << "error: " << error << "\n";
      return 1;
    }
    repair->SetInputData(mesh);
    surface = repair;
  }
  else
  {
    // The command line's settings, else the replayed session's, else the
    // defaults; the session saved later records what was used.
    Session::Surface& used = planner.session.surface;
    if (isoGiven)
      used.iso = iso;
    if (seeded)
    {
      used.seeded = true;
      used.seed = { seed[0], seed[1], seed[2] };
    }
    if (cropped)
    {
      used.cropped = true;
      std::copy(crop, crop + 6, used.crop.begin());
    }
    if (closed)
      used.closed = true;
    if (series >= 0)
      used.series = series;
    if (smoothing >= 0)
      used.smoothing = smoothing;
    if (imageSmoothing >= 0.0)
      used.imageSmoothing = imageSmoothing;
    if (label > 0 || !labelName.empty())
    {
      used.label = label;
      used.labelName = labelName;
    }
    used.given = true;
    if (headGiven)
    {
      planner.session.patientGiven = true;
      planner.session.patient = patient;
    }
    reader->SetFileName(input.c_str());
    reader->SetSeriesIndex(static_cast<int>(used.series));
    bone->SetInputConnection(reader->GetOutputPort());
    bone->SetIsoValue(used.iso);
    if (used.seeded)
    {
      bone->SetExtractionModeToSeededComponent();
      bone->SetSeedPoint(used.seed.data());
    }
    bone->SetCropping(used.cropped);
    bone->SetCropBox(used.crop.data());
    bone->SetCloseAtBorder(used.closed);
    bone->SetSmoothingIterations(static_cast<int>(used.smoothing));
    bone->SetImageSmoothing(used.imageSmoothing);
    if (used.labelMapDefaultsOfBefore)
    {
      bone->SetLabelMapImageSmoothing(1.0);
      bone->SetLabelMapSmoothingIterations(0);
    }
    bone->SetLabel(static_cast<int>(used.label));
    bone->SetLabelName(used.labelName.empty() ? nullptr : used.labelName.c_str());
  }
  const int warningsBeforeLoad = lkapp::warningCount();
  std::string organNote; // the organ read from an RT structure set beside the CT
  {
    // Before the window opens, a large CT takes a while: bars in a terminal
    // (not in a log, where the headless runs' reports are read line by line).
    const bool bars = isatty(STDERR_FILENO) != 0;
    if (!mesh)
    {
      lkapp::ProgressBar bar(reader, "read", bars);
      reader->Update();
      // The scan, for the CT on a cut line's plane (c, the export's
      // pictures); kept before an organ's structure set replaces it.
      if (lkapp::errorCount() == 0)
      {
        planner.scan = vtkSmartPointer<vtkImageData>::New();
        planner.scan->ShallowCopy(reader->GetOutput());
        planner.scanToPatient->DeepCopy(reader->GetPatientMatrix());
      }
    }
    // --label NAME on a CT exported with the organs contoured on it (a
    // radiotherapy export): the organ is read from the RT structure set,
    // and the window says so.
    if (!mesh && lkapp::errorCount() == 0)
    {
      if (lkapp::readOrganFromStructureSet(reader, planner.session.surface.labelName, organNote, error))
        std::cerr << "note: " << organNote << "\n";
      else if (!error.empty())
      {
        std::cerr << "error: " << error << "\n";
        return 1;
      }
    }
    if (lkapp::errorCount() == 0) // a scan that cannot be read is said once
    {
      lkapp::ProgressBar bar(surface, mesh ? "repair" : "surface", bars);
      surface->Update();
    }
  }
  if (lkapp::errorCount() > 0 || surface->GetOutput()->GetNumberOfPolys() == 0)
  {
    if (lkapp::errorCount() == 0) // VTK's errors are printed as they come (installMessageHandler)
      std::cerr << "error: no surface in " << input << "\n";
    return 1;
  }
  planner.bone = vtkSmartPointer<vtkPolyData>::New();
  planner.bone->ShallowCopy(surface->GetOutput());
  planner.scanIsLabelMap = !mesh && organNote.empty() && bone->GetTreatedAsLabelMap();
  if (!mesh) // the session keeps what was used, so that a replay makes the same surface whatever the defaults
  {
    planner.session.surface.imageSmoothing = bone->GetEffectiveImageSmoothing();
    planner.session.surface.smoothing = bone->GetEffectiveSmoothingIterations();
    planner.session.surface.labelMapDefaultsOfBefore = false;
  }
  planner.input = vtksys::SystemTools::CollapseFullPath(input);
  if (!mesh)
    planner.referenceImage = reader->GetReferenceImageFileName();
  // A segmentation file (a DICOM SEG, an RT structure set) drawn on a CT
  // that lies beside it: the view shows that CT, read when first shown.
  if (!mesh && organNote.empty() && planner.scanIsLabelMap && !planner.referenceImage.empty() &&
    (std::strcmp(reader->GetFileFormat(), "DICOM SEG") == 0 || std::strcmp(reader->GetFileFormat(), "DICOM RTSTRUCT") == 0))
    planner.scanFile = planner.referenceImage;
  planner.checkReplayedInput(!replay.empty());
  if (!ignoredFields.empty())
    planner.inputWarnings += (planner.inputWarnings.empty() ? "" : "\n") + ignoredFields;
  // What reading the scan and making its surface warned of (a slice missing,
  // several series, no orientation) is shown in the window too, where the
  // surgeon looks, and not only in the terminal.
  std::string loadWarnings = lkapp::warningsSince(warningsBeforeLoad);
  if (!mesh && isoGiven && bone->GetTreatedAsLabelMap())
  {
    const std::string note = lkapp::unusedIsoNote(iso, bone->GetEffectiveLabel(), input, false);
    std::cerr << "warning: " << note << "\n";
    loadWarnings += (loadWarnings.empty() ? "" : "\n") + note;
  }
  if (!organNote.empty())
    loadWarnings += (loadWarnings.empty() ? "" : "\n") + organNote;
  if (!loadWarnings.empty())
    planner.inputWarnings += (planner.inputWarnings.empty() ? "" : "\n") + loadWarnings;
  if (mesh) // the file's coordinate system (3D Slicer's tag), which the export names again
    lkapp::setCoordinateSpace(planner.bone, lkapp::coordinateSpace(mesh));
  if (!mesh)
  {
    const Session::Surface& used = planner.session.surface;
    std::cout << "surface: " << planner.bone->GetNumberOfPoints() << " points, "
              << planner.bone->GetNumberOfPolys() << " triangles ("
              << (bone->GetTreatedAsLabelMap() ? "label map at level " : "CT at ") << bone->GetEffectiveIsoValue()
              << (bone->GetTreatedAsLabelMap() ? "" : " HU") << ", ";
    if (bone->GetEffectiveLabel() > 0)
      std::cout << "label " << bone->GetEffectiveLabel()
                << (*bone->GetEffectiveSegmentName() ? " (segment '" + std::string(bone->GetEffectiveSegmentName()) + "')"
                                                      : std::string())
                << ", ";
    if (used.cropped)
      std::cout << "inside the box x " << used.crop[0] << " to " << used.crop[1] << ", y " << used.crop[2] << " to "
                << used.crop[3] << ", z " << used.crop[4] << " to " << used.crop[5] << ", ";
    else if (used.closed)
      std::cout << "closed where the scan's border cuts bone, ";
    if (used.seeded)
      std::cout << "the component nearest (" << used.seed[0] << ", " << used.seed[1] << ", " << used.seed[2] << ")";
    else
      std::cout << "the largest component";
    if (reader->GetNumberOfSeries() > 0)
      std::cout << ", series " << std::max<long>(0, used.series) << " of " << reader->GetNumberOfSeries();
    if (used.imageSmoothing > 0.0)
      std::cout << ", a Gaussian of " << used.imageSmoothing << " voxel on the volume";
    if (used.smoothing > 0)
      std::cout << ", smoothed (" << used.smoothing << " windowed-sinc iterations)";
    std::cout << ")\n";
  }
  else
  {
    const double merged = lkapp::fieldValue(planner.bone, "MergedPoints"),
                 degenerate = lkapp::fieldValue(planner.bone, "RemovedDegenerateFaces"),
                 split = lkapp::fieldValue(planner.bone, "SplitNonManifoldVertices");
    std::cout << "mesh: " << planner.bone->GetNumberOfPoints() << " points, " << planner.bone->GetNumberOfPolys()
              << " triangles";
    if (mesh->GetNumberOfPolys() != planner.bone->GetNumberOfPolys() || merged > 0 || degenerate > 0 || split > 0)
      std::cout << " (repaired from " << mesh->GetNumberOfPolys() << " faces: " << merged << " points merged, "
                << degenerate << " degenerate faces removed, " << split << " non-manifold vertices split)";
    std::cout << "\n";
  }
  if (const std::string space = lkapp::coordinateSpace(planner.bone); !space.empty())
    std::cout << "space: " << space << " patient coordinates (the cube at the top right shows the patient's sides)\n";
  else
    std::cout << "space: unknown, " << (mesh ? "the mesh file names none" : "the volume gives no orientation")
              << " (no orientation cube)\n";
  // After the input and the session are read, so that their problems are
  // named first.
  // The window's connection, before anything renders or the interactor
  // opens one (see openDisplay).
  void* display = lkapp::openDisplay();
  if (!display)
  {
    std::cerr << "error: the planner needs an X display (DISPLAY is not set, or names no running server); headless, "
                 "run it under xvfb-run -a "
                 "with --screenshot, --export or --events\n";
    return 1;
  }
  planner.window->SetDisplayId(display);
  planner.setup();
  planner.rebuild();
  planner.renderer->ResetCamera();
  if (planner.patientStated())
  {
    // The first view from the patient's front, the head up, as stated.
    vtkCamera* camera = planner.renderer->GetActiveCamera();
    std::array<double, 3> towardFront = planner.session.patient.front;
    vtkMath::Normalize(towardFront.data());
    double focal[3];
    camera->GetFocalPoint(focal);
    const double distance = camera->GetDistance();
    camera->SetPosition(focal[0] + distance * towardFront[0], focal[1] + distance * towardFront[1],
      focal[2] + distance * towardFront[2]);
    camera->SetViewUp(planner.session.patient.head.data());
    camera->OrthogonalizeViewUp();
    planner.renderer->ResetCamera();
  }
  else if (planner.session.patientGiven && !mesh)
    std::cerr << "warning: the scan gives its own orientation: the stated head and front (--head, --front, the "
                 "session's \"patient\") are not used\n";
  const bool batch = !shot.empty() || !exportFolder.empty() || !events.empty();
  planner.savedSession = sessionText(planner.session);
  if (!batch || !events.empty()) // a user's session, live or played
  {
    planner.unsavedPath = unsavedSessionPath(sessionOut);
    planner.showWork = true;
  }
  if (!events.empty())
  {
    // Headless interaction: the recorded events go through the real style.
    if (!vtksys::SystemTools::FileExists(events) || vtksys::SystemTools::FileIsDirectory(events))
    {
      std::cerr << "error: cannot open '" << events << "'\n";
      return 1;
    }
    // A device (/dev/zero) never ends; a pipe (bash's <(...)) is read as it comes.
    if (lkapp::specialFileKind(events) == "device")
    {
      std::cerr << "error: cannot read the events '" << events << "': it is a device, not a file\n";
      return 1;
    }
    planner.window->SetOffScreenRendering(1);
    vtkNew<vtkRenderWindowInteractor> interactor;
    vtkNew<PlannerStyle> style;
    style->planner = &planner;
    style->sessionPath = sessionOut;
    interactor->SetInteractorStyle(style);
    interactor->SetRenderWindow(planner.window);
    interactor->Initialize();
    planner.window->Render();
    // The event stream in vtkInteractorEventRecorder's documented format
    // (EventName X Y ctrl shift keycode repeatCount keySym, '#' comments),
    // invoked on the interactor one by one.
    std::ifstream in(events);
    std::string line;
    int played = 0;
    int lineNumber = 0;
    // A line as it can be printed: control and non-ASCII bytes as '?', at most 80 characters.
    auto printable = [](const std::string& text) {
      std::string shown = text.substr(0, 80);
      for (char& ch : shown)
        if (static_cast<unsigned char>(ch) < 32 || static_cast<unsigned char>(ch) > 126)
          ch = '?';
      return text.size() > 80 ? shown + "..." : shown;
    };
    while (std::getline(in, line))
    {
      ++lineNumber;
      if (line.empty() || line[0] == '#')
        continue;
      std::istringstream fields(line);
      std::string name, keyCode, keySym;
      int x = 0, y = 0, ctrl = 0, shift = 0, repeat = 0;
      if (!(fields >> name >> x >> y >> ctrl >> shift >> keyCode >> repeat >> keySym))
      {
        std::cerr << "error: cannot read event line " << lineNumber << " of '" << events << "' (EventName X Y ctrl shift keycode repeat keysym): '" << printable(line) << "'\n";
        return 1;
      }
      const unsigned long id = vtkCommand::GetEventIdFromString(name.c_str());
      if (id == vtkCommand::NoEvent)
      {
        std::cerr << "error: unknown event '" << name << "'\n";
        return 1;
      }
      const char code = keyCode.size() == 1 ? keyCode[0] : static_cast<char>(std::atoi(keyCode.c_str()));
      interactor->SetEventInformation(x, y, ctrl, shift, code, repeat, keySym == "0" ? nullptr : keySym.c_str());
      interactor->InvokeEvent(id, nullptr);
      ++played;
      if (style->quitRequested)
        break; // the window would close here
    }
    std::printf("events: %d\n", played);
    if (style->quitRequested && !keepUnsavedSession(planner))
      return 1;
  }
  if (batch)
  {
    planner.report();
    if (!exportFolder.empty() && !planner.exportPieces(exportFolder, error))
    {
      std::cerr << "error: " << error << "\n";
      return 1;
    }
    if (!exportFolder.empty() && !planner.exportNote.empty())
      std::cout << "structure set: " << planner.exportNote << "\n";
    if (!shot.empty())
    {
      planner.window->SetOffScreenRendering(1);
      if (!planner.screenshot(shot, error))
      {
        std::cerr << "error: " << error << "\n";
        return 1;
      }
      std::printf("screenshot: %s\n", shot.c_str());
    }
    return planner.cutFailed ? 1 : 0;
  }
  vtkNew<vtkRenderWindowInteractor> interactor;
  vtkNew<PlannerStyle> style;
  style->planner = &planner;
  style->sessionPath = sessionOut;
  interactor->SetInteractorStyle(style);
  interactor->SetRenderWindow(planner.window);
  planner.window->Render();
  interactor->Start(); // until 'q', Escape or the window's close button
  return keepUnsavedSession(planner) ? 0 : 1;
}
