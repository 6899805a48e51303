// latticekit-demo: the main job on a CT. Version 0 (until the lattice exists):
// CT -> bone surface -> decimated copy (vtkQuadricDecimation) -> Metro error of
// the copy against the surface -> files, a short report and a PNG of the
// error painted on the surface.
#include "common/AppSupport.h"

#include "vtkLKBoneSurfaceFilter.h"
#include "vtkLKMedicalImageReader.h"
#include "vtkLKMetroFilter.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkPolyDataNormals.h>
#include <vtkProperty.h>
#include <vtkQuadricDecimation.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>
#include <vtksys/SystemTools.hxx>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>

#ifndef LATTICEKIT_SOURCE_DIR
#define LATTICEKIT_SOURCE_DIR "."
#endif

namespace
{
void usage(std::ostream& os)
{
  os << "usage: latticekit-demo [INPUT] [-o FOLDER] [options]\n"
        "\n"
        "Runs the main job: CT -> bone surface -> simplified copy -> Metro error -> files,\n"
        "report.md and error.png in FOLDER (default: latticekit-output).\n"
        "INPUT defaults to the bundled CT head (sample_data/cthead/cthead_hu_approx.nii.gz).\n"
        "\n"
        "  --iso V          bone iso value in HU (default 300)\n"
        "  --vertices N     vertices of the simplified copy (default 20000)\n"
        "  --samples N      Metro face samples per direction (default: 10 per face)\n"
        "  --smooth N       windowed-sinc smoothing iterations of the bone (default 10)\n"
        "  --view-from X,Y,Z  direction from the surface to the camera, patient coordinates\n"
        "                   (default 0,-1,0: anterior in LPS)\n"
        "  --view-up X,Y,Z  camera up direction (default 0,0,1: superior)\n"
        "  --no-render      skip the PNG (it needs an X display: run under xvfb-run)\n"
        "  -q, --quiet      no progress bars\n"
        "  -h, --help       this help\n";
}

double field(vtkPolyData* pd, const char* name)
{
  vtkDataArray* a = pd->GetFieldData()->GetArray(name);
  return a ? a->GetTuple1(0) : 0.0;
}

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t)
{
  return std::chrono::duration<double>(Clock::now() - t).count();
}

bool renderError(vtkPolyData* colored, double maxDistance, const double viewFrom[3],
  const double viewUp[3], const std::string& title, const std::string& png, std::string& error)
{
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputData(colored);
  normals->SplittingOff();
  normals->ConsistencyOff();
  normals->AutoOrientNormalsOff();
  vtkNew<vtkLookupTable> lut;
  lut->SetHueRange(0.667, 0.0);
  lut->SetTableRange(0.0, maxDistance > 0 ? maxDistance : 1.0);
  lut->Build();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(normals->GetOutputPort());
  mapper->SetScalarModeToUsePointFieldData();
  mapper->SelectColorArray("Distance");
  mapper->SetLookupTable(lut);
  mapper->SetScalarRange(0.0, maxDistance > 0 ? maxDistance : 1.0);
  mapper->ScalarVisibilityOn();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetInterpolationToGouraud();
  actor->GetProperty()->SetSpecular(0.2);
  vtkNew<vtkScalarBarActor> bar;
  bar->SetLookupTable(lut);
  bar->SetTitle("distance (mm)");
  lut->SetAboveRangeColor(1.0, 0.0, 0.0, 1.0);
  lut->UseAboveRangeColorOn();
  bar->SetNumberOfLabels(5);
  bar->SetMaximumWidthInPixels(90);
  bar->GetTitleTextProperty()->SetFontSize(14);
  vtkNew<vtkTextActor> text;
  text->SetInput(title.c_str());
  text->GetTextProperty()->SetFontSize(16);
  text->SetDisplayPosition(10, 10);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->AddViewProp(bar);
  renderer->AddViewProp(text);
  renderer->SetBackground(1.0, 1.0, 1.0);
  text->GetTextProperty()->SetColor(0, 0, 0);
  bar->GetLabelTextProperty()->SetColor(0, 0, 0);
  bar->GetTitleTextProperty()->SetColor(0, 0, 0);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0, 0, 0);
  camera->SetPosition(viewFrom);
  camera->SetViewUp(viewUp);
  renderer->ResetCamera();
  camera->Zoom(1.25);
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  window->SetSize(900, 800);
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName(png.c_str());
  writer->Write();
  if (!vtksys::SystemTools::FileExists(png, true))
  {
    error = "could not write " + png;
    return false;
  }
  return true;
}
} // namespace

int main(int argc, char* argv[])
{
  std::string input = std::string(LATTICEKIT_SOURCE_DIR) + "/sample_data/cthead/cthead_hu_approx.nii.gz";
  std::string folder = "latticekit-output";
  double iso = 300.0;
  long vertices = 20000, samples = 0, smooth = 10;
  double viewFrom[3] = { 0, -1, 0 }, viewUp[3] = { 0, 0, 1 };
  bool render = true, quiet = false, inputGiven = false;
  lkapp::Arguments args(argc, argv, usage);
  std::string a;
  while (args.next(a))
  {
    if (a == "-o" || a == "--output")
      folder = args.value(a);
    else if (a == "--iso")
      iso = args.number(a, -std::numeric_limits<double>::max(), std::numeric_limits<double>::max(), "a number");
    else if (a == "--vertices")
      vertices = args.integer(a, 4, std::numeric_limits<long>::max(), "an integer >= 4");
    else if (a == "--samples")
      samples = args.integer(a, 1, std::numeric_limits<long>::max(), "a positive integer");
    else if (a == "--smooth")
      smooth = args.integer(a, 0, 1000, "an integer from 0 to 1000");
    else if (a == "--view-from")
      args.triple(a, viewFrom);
    else if (a == "--view-up")
      args.triple(a, viewUp);
    else if (a == "--no-render")
      render = false;
    else if (a == "-q" || a == "--quiet")
      quiet = true;
    else if (lkapp::Arguments::isOption(a))
      args.unknown(a);
    else if (!inputGiven)
    {
      input = a;
      inputGiven = true;
    }
    else
    {
      std::cerr << "error: more than one input given\n";
      return 2;
    }
  }
  lkapp::installMessageHandler(quiet);
  if (!vtksys::SystemTools::MakeDirectory(folder))
  {
    std::cerr << "error: cannot create the output folder '" << folder << "'\n";
    return 1;
  }
  std::string error;
  const auto start = Clock::now();

  std::cout << "latticekit main job (v0): " << input << "\n";
  vtkNew<vtkLKMedicalImageReader> reader;
  reader->SetFileName(input.c_str());
  reader->Update();
  if (lkapp::errorCount() > 0)
  {
    return 1;
  }
  const double tRead = since(start);

  auto t = Clock::now();
  vtkNew<vtkLKBoneSurfaceFilter> bone;
  bone->SetInputConnection(reader->GetOutputPort());
  bone->SetIsoValue(iso);
  bone->SetSmoothingIterations(static_cast<int>(smooth));
  {
    lkapp::ProgressBar bar(bone, "bone surface ", !quiet);
    bone->Update();
  }
  if (lkapp::errorCount() > 0)
  {
    return 1;
  }
  vtkPolyData* surface = bone->GetOutput();
  const double tSurface = since(t);

  t = Clock::now();
  vtkNew<vtkQuadricDecimation> decimate;
  decimate->SetInputData(surface);
  const double reduction =
    1.0 - static_cast<double>(vertices) / static_cast<double>(surface->GetNumberOfPoints());
  if (reduction <= 0.0)
  {
    std::cerr << "error: the surface has only " << surface->GetNumberOfPoints()
              << " points; ask for fewer --vertices\n";
    return 1;
  }
  decimate->SetTargetReduction(reduction);
  decimate->VolumePreservationOn();
  {
    lkapp::ProgressBar bar(decimate, "simplify     ", !quiet);
    decimate->Update();
  }
  vtkPolyData* simplified = decimate->GetOutput();
  const double tDecimate = since(t);

  t = Clock::now();
  vtkNew<vtkLKMetroFilter> metro;
  metro->SetInputData(surface);
  metro->SetTargetData(simplified);
  metro->SetNumberOfSamples(samples);
  {
    lkapp::ProgressBar bar(metro, "metro        ", !quiet);
    metro->Update();
  }
  if (lkapp::errorCount() > 0)
  {
    return 1;
  }
  vtkPolyData* colored = metro->GetOutput();
  const double tMetro = since(t);

  const std::string boneFile = folder + "/bone.vtp";
  const std::string boneStl = folder + "/bone.stl";
  const std::string simplifiedFile = folder + "/simplified.vtp";
  const std::string coloredFile = folder + "/bone_error.vtp";
  for (auto [mesh, path] : { std::pair<vtkPolyData*, std::string>{ surface, boneFile },
         { surface, boneStl }, { simplified, simplifiedFile }, { colored, coloredFile } })
  {
    if (!lkapp::writeMesh(mesh, path, error))
    {
      std::cerr << "error: " << error << "\n";
      return 1;
    }
  }

  const double samplesTotal = field(colored, "AtoB_Samples") + field(colored, "BtoA_Samples");
  std::ostringstream report;
  report << "# latticekit main job (v0)\n\n"
         << "Input: `" << input << "` (" << reader->GetFileFormat() << ")\n\n"
         << "| step | result | seconds |\n|---|---|---|\n"
         << "| read | " << reader->GetOutput()->GetDimensions()[0] << " x "
         << reader->GetOutput()->GetDimensions()[1] << " x " << reader->GetOutput()->GetDimensions()[2]
         << " voxels | " << tRead << " |\n"
         << "| bone surface (iso " << bone->GetEffectiveIsoValue() << ", largest component, repaired, "
         << smooth << " smoothing iterations) | "
         << surface->GetNumberOfPoints() << " vertices, " << surface->GetNumberOfPolys()
         << " triangles, " << field(surface, "BoundaryEdges") << " boundary edges | " << tSurface
         << " |\n"
         << "| simplified copy (vtkQuadricDecimation) | " << simplified->GetNumberOfPoints()
         << " vertices, " << simplified->GetNumberOfPolys() << " triangles | " << tDecimate << " |\n"
         << "| Metro | " << samplesTotal << " samples | " << tMetro << " |\n\n";
  char line[512];
  report << "Metro error of the simplified copy against the bone surface "
            "(bounding-box diagonal "
         << field(colored, "BoundingBoxDiagonal") << " mm):\n\n"
         << "| direction | max (mm) | mean (mm) | RMS (mm) | max % | mean % | RMS % |\n"
         << "|---|---|---|---|---|---|---|\n";
  for (auto [label, p] : { std::pair<const char*, std::string>{ "surface -> copy", "AtoB" },
         { "copy -> surface", "BtoA" }, { "symmetric", "Hausdorff" } })
  {
    std::snprintf(line, sizeof(line), "| %s | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f |\n", label,
      field(colored, (p + "_Max").c_str()), field(colored, (p + "_Mean").c_str()),
      field(colored, (p + "_RMS").c_str()), field(colored, (p + "_MaxPercent").c_str()),
      field(colored, (p + "_MeanPercent").c_str()), field(colored, (p + "_RMSPercent").c_str()));
    report << line;
  }
  report << "\nFiles: `bone.vtp`, `bone.stl` (surface in patient coordinates, mm), `simplified.vtp`, "
            "`bone_error.vtp` (surface with point data Distance and DistanceColors)";

  if (render)
  {
    if (!std::getenv("DISPLAY"))
    {
      std::cerr << "note: no X display, so no error.png (run under xvfb-run -a, or pass --no-render)\n";
      report << ".\n";
    }
    else
    {
      std::snprintf(line, sizeof(line),
        "Metro error of a %lld-vertex copy: max %.3f%%, mean %.4f%% of bbox diagonal",
        static_cast<long long>(simplified->GetNumberOfPoints()), field(colored, "Hausdorff_MaxPercent"),
        field(colored, "Hausdorff_MeanPercent"));
      if (!renderError(colored, metro->GetEffectiveColorMaximum(), viewFrom, viewUp, line,
            folder + "/error.png", error))
      {
        std::cerr << "error: " << error << "\n";
        return 1;
      }
      report << ", `error.png` (error painted on the surface, blue 0 to red "
             << metro->GetEffectiveColorMaximum()
             << " mm, the 99th percentile of the point distances).\n";
    }
  }
  else
  {
    report << ".\n";
  }
  report << "\nTotal " << since(start) << " s.\n";
  std::ofstream(folder + "/report.md") << report.str();
  std::cout << "\n" << report.str();
  std::cout << "\nResults in " << folder << "/\n";
  return lkapp::errorCount() > 0 ? 1 : 0;
}
