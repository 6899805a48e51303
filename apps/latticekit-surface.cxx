// latticekit-surface: CT volume or label map -> manifold bone surface.
#include "common/AppSupport.h"

#include "vtkLKBoneSurfaceFilter.h"
#include "vtkLKMedicalImageReader.h"
#include "vtkLKStructureSetWriter.h"
#include "vtkLKText.h"

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkMassProperties.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtksys/SystemTools.hxx>

#include <chrono>
#include <cstring>
#include <iostream>
#include <limits>
#include <string>

namespace
{
void usage(std::ostream& os)
{
  os << "usage: latticekit-surface INPUT -o OUTPUT [options]\n"
        "\n"
        "INPUT is a DICOM folder (or a file of the series, a DICOM SEG or an RT structure set),\n"
        ".nrrd/.nhdr, .mha/.mhd or .nii/.nii.gz.\n"
        "OUTPUT is written by extension: .vtp, .vtk, .stl, .ply or .obj (patient LPS coordinates, mm),\n"
        "or .dcm: an RT structure set (the surface as an ROI; on the slices of the DICOM CT it came\n"
        "from, or that a structure set or SEG given lies beside, in the CT's study).\n"
        "\n"
        "  --iso V            iso value (default 300, bone in HU; label maps use 0.5)\n"
        "  --largest          keep the largest component (default)\n"
        "  --all              keep every component\n"
        "  --seed X,Y,Z       keep the component closest to this patient-space point\n"
        "  --crop X0,X1,Y0,Y1,Z0,Z1\n"
        "                     only the volume inside this patient-space box (mm), padded with\n"
        "                     air so that the surface closes where the box cuts bone\n"
        "  --close            close the surface where the scan's border cuts bone (padded\n"
        "                     with air as a crop is): a skull vault above the last slice\n"
        "  --smooth N         windowed-sinc smoothing iterations on the surface (default:\n"
        "                     20 for label maps, which takes the slice staircase out, none\n"
        "                     for CT)\n"
        "  --image-smooth S   Gaussian smoothing of the volume, std. dev. in voxels\n"
        "                     (default: 0.5 for label maps, none for CT). With 20 iterations\n"
        "                     this followed label maps of known shapes most closely; one\n"
        "                     voxel (--image-smooth 1 --smooth 0, the default before December\n"
        "                     2026) wears thin processes down across 2.5 mm slices (a\n"
        "                     coronoid's tip by 3 to 6 mm)\n"
        "  --label-map        treat the input as a 0/1 label map (auto-detected otherwise)\n"
        "  --no-label-map     never treat the input as a label map\n"
        "  --label N|NAME     one label of a label map with several (a segmentation: its\n"
        "                     voxels of value N, as a 0/1 label map), or a segment of a\n"
        "                     segmentation (.seg.nrrd, DICOM SEG) or an ROI of an RT\n"
        "                     structure set by its name\n"
        "  --roi NAME         the ROI's name in a .dcm OUTPUT (default: the segment's name,\n"
        "                     or Bone; up to 64 characters, no backslash)\n"
        "  --series I         DICOM: read series I of the folder (0 = largest, the default)\n"
        "  --slice-spacing H  DICOM: resampled slice spacing in mm (default: smallest gap)\n"
        "  --fill-cavities    fill enclosed air (in 3D or within a slice) first: the outer\n"
        "                     surface only, e.g. the skin at --iso -400 without sinuses,\n"
        "                     airway and mouth\n"
        "  --no-repair        skip the manifold repair\n"
        "  -q, --quiet        no progress bar\n"
        "  -h, --help         this help\n";
}
} // namespace

int main(int argc, char* argv[])
{
  lkapp::installCrashReport("latticekit-surface");
  std::string input, output;
  bool isoGiven = false;
  double iso = 300.0, imageSmooth = -1.0, seed[3] = { 0, 0, 0 }, crop[6] = { 0, 0, 0, 0, 0, 0 };
  bool cropping = false, close = false;
  long smooth = -1, series = -1;
  double sliceSpacing = 0.0;
  int mode = vtkLKBoneSurfaceFilter::LARGEST_COMPONENT;
  int labelMode = vtkLKBoneSurfaceFilter::LABEL_MAP_AUTO;
  long label = 0;
  std::string labelName, roiName;
  std::string componentOption, labelMapOption; // the one given of each group that excludes each other
  bool repair = true, quiet = false, fillCavities = false;
  lkapp::Arguments args(argc, argv, usage);
  const double inf = std::numeric_limits<double>::max();
  std::string a;
  while (args.next(a))
  {
    if (a == "-o" || a == "--output")
      output = args.value(a);
    else if (a == "--iso")
    {
      iso = args.number(a, -inf, inf, "a number");
      isoGiven = true;
    }
    else if (a == "--largest")
    {
      args.exclusive(a, componentOption);
      mode = vtkLKBoneSurfaceFilter::LARGEST_COMPONENT;
    }
    else if (a == "--all")
    {
      args.exclusive(a, componentOption);
      mode = vtkLKBoneSurfaceFilter::ALL_COMPONENTS;
    }
    else if (a == "--seed")
    {
      args.exclusive(a, componentOption);
      args.triple(a, seed);
      mode = vtkLKBoneSurfaceFilter::SEEDED_COMPONENT;
    }
    else if (a == "--crop")
    {
      args.box(a, crop);
      cropping = true;
    }
    else if (a == "--close")
      close = true;
    else if (a == "--smooth")
      smooth = args.integer(a, 0, 1000, "an integer from 0 to 1000");
    else if (a == "--image-smooth")
      imageSmooth = args.number(a, 0.0, 20.0, "a number from 0 to 20");
    else if (a == "--label-map")
    {
      args.exclusive(a, labelMapOption);
      labelMode = vtkLKBoneSurfaceFilter::LABEL_MAP_ON;
    }
    else if (a == "--no-label-map")
    {
      args.exclusive(a, labelMapOption);
      labelMode = vtkLKBoneSurfaceFilter::LABEL_MAP_OFF;
    }
    else if (a == "--label")
      args.labelOrName(a, label, labelName);
    else if (a == "--roi")
      roiName = args.value(a);
    else if (a == "--series")
      series = args.integer(a, 0, std::numeric_limits<long>::max(), "an integer >= 0");
    else if (a == "--slice-spacing")
      sliceSpacing = args.number(a, std::numeric_limits<double>::min(), inf, "a positive number");
    else if (a == "--fill-cavities")
      fillCavities = true;
    else if (a == "--no-repair")
      repair = false;
    else if (a == "-q" || a == "--quiet")
      quiet = true;
    else if (lkapp::Arguments::isOption(a))
      args.unknown(a);
    else
      args.positional(a, input, "input");
  }
  if ((label > 0 || !labelName.empty()) && labelMode == vtkLKBoneSurfaceFilter::LABEL_MAP_OFF)
  {
    std::cerr << "error: --label takes one label of a label map; --no-label-map says the input is none\n";
    return 2;
  }
  const bool structureSet =
    vtksys::SystemTools::LowerCase(vtksys::SystemTools::GetFilenameLastExtension(output)) == ".dcm";
  if (!roiName.empty() && !structureSet)
  {
    std::cerr << "error: --roi names the ROI of a .dcm OUTPUT (an RT structure set)\n";
    return 2;
  }
  if (const std::string problem = lkvtk::dicomTextProblem(roiName, lkvtk::kDICOMLongStringLength);
      !roiName.empty() && !problem.empty())
  {
    std::cerr << "error: --roi: the name " << problem << "\n";
    return 2;
  }
  if (input.empty() || output.empty())
  {
    std::cerr << "error: an INPUT and -o OUTPUT are required\n";
    usage(std::cerr);
    return 2;
  }
  lkapp::installMessageHandler(quiet);
  std::string error;
  if (!lkapp::checkWritable(output, error, true))
  {
    std::cerr << "error: " << error << "\n";
    return 1;
  }

  const auto start = std::chrono::steady_clock::now();
  vtkNew<vtkLKMedicalImageReader> reader;
  reader->SetFileName(input.c_str());
  reader->SetSeriesIndex(static_cast<int>(series));
  reader->SetSliceSpacing(sliceSpacing);
  {
    lkapp::ProgressBar bar(reader, "read", !quiet); // a DICOM folder of hundreds of slices takes a while
    reader->Update();
  }
  if (lkapp::errorCount() > 0)
  {
    return 1;
  }
  // --label NAME on a CT exported with the organs contoured on it (a
  // radiotherapy export): the organ is read from the RT structure set.
  if (std::string note; lkapp::readOrganFromStructureSet(reader, labelName, note, error))
    std::cerr << "note: " << note << "\n";
  else if (!error.empty())
  {
    std::cerr << "error: " << error << "\n";
    return 1;
  }
  vtkNew<vtkLKBoneSurfaceFilter> surface;
  surface->SetInputConnection(reader->GetOutputPort());
  surface->SetIsoValue(iso);
  surface->SetImageSmoothing(imageSmooth);
  surface->SetSmoothingIterations(static_cast<int>(smooth));
  surface->SetExtractionMode(mode);
  surface->SetSeedPoint(seed);
  surface->SetCropping(cropping);
  surface->SetCropBox(crop);
  surface->SetCloseAtBorder(close);
  surface->SetLabelMapMode(labelMode);
  surface->SetLabel(static_cast<int>(label));
  surface->SetLabelName(labelName.empty() ? nullptr : labelName.c_str());
  surface->SetRepair(repair);
  surface->SetFillCavities(fillCavities);
  {
    lkapp::ProgressBar bar(surface, "surface", !quiet);
    surface->Update();
  }
  if (lkapp::errorCount() > 0)
  {
    return 1;
  }
  if (isoGiven && surface->GetTreatedAsLabelMap())
  {
    // A label map is taken at 0.5 whatever --iso says: say so, as the
    // surface is not the one asked for.
    std::cerr << "warning: "
              << lkapp::unusedIsoNote(iso, surface->GetEffectiveLabel(), input,
                   labelMode == vtkLKBoneSurfaceFilter::LABEL_MAP_AUTO)
              << "\n";
  }
  vtkPolyData* mesh = surface->GetOutput();
  std::string written;
  if (structureSet)
  {
    // An RT structure set, for a PACS viewer or a planning system: the
    // surface as an ROI, its contours on the CT's slices when the input is
    // a DICOM CT, or a structure set or DICOM SEG drawn on one that lies
    // beside it (the set then belongs to the CT's patient and study).
    vtkNew<vtkLKStructureSetWriter> set;
    set->SetInputData(mesh);
    // A segment's name from a segmentation file can be longer than an ROI
    // name may be, or hold a backslash: it is fitted, and the change said.
    const std::string segment = surface->GetEffectiveSegmentName();
    std::string roi = roiName.empty() ? (segment.empty() ? "Bone" : lkvtk::fittedDicomText(segment, lkvtk::kDICOMLongStringLength)) : roiName;
    if (roi.empty())
      roi = "Bone";
    if (roiName.empty() && !segment.empty() && roi != segment)
      std::cerr << "warning: the segment's name is written as the ROI name '" << roi
                << "' (64 characters at most, no backslash or control character); --roi gives another\n";
    set->SetROIName(0, roi.c_str());
    const bool onTheCT = *reader->GetReferenceImageFileName() != '\0';
    if (onTheCT)
      set->SetReferenceFileName(reader->GetReferenceImageFileName());
    set->SetFileName(output.c_str());
    set->Write();
    if (lkapp::errorCount() > 0)
      return 1;
    written = " (RT structure set, ROI '" + std::string(set->GetROIName(0)) + "': " +
      std::to_string(set->GetNumberOfContours()) + " contours on " +
      (onTheCT ? "the CT's slices" : "axial planes 1 mm apart") + ")";
  }
  else if (!lkapp::writeMesh(mesh, output, error))
  {
    std::cerr << "error: " << error << "\n";
    return 1;
  }
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  int dims[3];
  reader->GetOutput()->GetDimensions(dims);
  std::cout << "input      " << input << " (" << reader->GetFileFormat() << ", " << dims[0] << " x "
            << dims[1] << " x " << dims[2] << ")\n";
  if (std::strcmp(reader->GetFileFormat(), "DICOM") == 0)
  {
    std::cout << "dicom      " << reader->GetNumberOfInputSlices() << " slices, gaps "
              << reader->GetMinimumSliceGap() << " to " << reader->GetMaximumSliceGap()
              << " mm, gantry tilt " << reader->GetGantryTilt() << " deg, series "
              << (series < 0 ? 0 : series) << " of " << reader->GetNumberOfSeries() << "\n";
  }
  if (close && !cropping)
    std::cout << "closed     where the scan's border cuts bone (padded with air)\n";
  if (cropping)
    std::cout << "crop box   x " << crop[0] << " to " << crop[1] << ", y " << crop[2] << " to " << crop[3] << ", z "
              << crop[4] << " to " << crop[5] << " mm (patient), padded with air\n";
  if (reader->GetNumberOfSegments() > 0)
  {
    // A segmentation's segments, so that the next run can name another.
    std::cout << "segments   ";
    for (int i = 0; i < reader->GetNumberOfSegments(); ++i)
      std::cout << (i ? ", " : "") << reader->GetSegmentLabelValue(i) << " '" << reader->GetSegmentName(i) << "'";
    const int layers = reader->GetOutput()->GetNumberOfScalarComponents();
    std::cout << (layers > 1 ? " (in " + std::to_string(layers) + " layers: they overlap)" : std::string()) << "\n";
  }
  if (std::strcmp(reader->GetFileFormat(), "DICOM RTSTRUCT") == 0 || std::strcmp(reader->GetFileFormat(), "DICOM SEG") == 0)
  {
    // Where the CT it was drawn on lies (its folder, or one beside it), or
    // that it was not found: a structure set is then filled on a grid of its
    // own, and -o X.dcm writes on axial planes in a new study.
    const std::string ct = reader->GetReferenceImageFileName();
    std::cout << "drawn on   "
              << (ct.empty() ? std::string("a CT not found in its folder or in one beside it")
                             : "the CT in '" + vtksys::SystemTools::GetFilenamePath(ct) + "'")
              << "\n";
  }
  const std::string segment = surface->GetEffectiveSegmentName();
  std::cout << "iso value  " << surface->GetEffectiveIsoValue()
            << (surface->GetEffectiveLabel() > 0
                   ? " (label " + std::to_string(surface->GetEffectiveLabel()) + " of the label map" +
                     (segment.empty() ? std::string() : ", segment '" + segment + "'") + ")"
                   : std::string(surface->GetTreatedAsLabelMap() ? " (label map)" : ""))
            << "\n";
  if (surface->GetEffectiveImageSmoothing() > 0.0 || surface->GetEffectiveSmoothingIterations() > 0)
    std::cout << "smoothing  "
              << lkapp::smoothingWords(surface->GetEffectiveImageSmoothing(), surface->GetEffectiveSmoothingIterations())
              << "\n";
  std::cout << "surface    " << mesh->GetNumberOfPoints() << " points, " << mesh->GetNumberOfPolys()
            << " triangles\n";
  auto field = [&](const char* name) -> long {
    vtkDataArray* a = mesh->GetFieldData()->GetArray(name);
    return a ? static_cast<long>(a->GetTuple1(0)) : -1;
  };
  if (repair)
  {
    const long boundary = field("BoundaryEdges");
    std::cout << "topology   manifold (CGAL Surface_mesh), " << field("Components")
              << " component(s), " << (boundary == 0 ? "closed" : "open with ") ;
    if (boundary != 0)
    {
      std::cout << boundary << " boundary edges";
      if (!cropping && !close)
        std::cout << " where the scan's border cuts bone (--close closes it)";
    }
    std::cout << "; repair merged " << field("MergedPoints") << " points, removed "
              << field("RemovedDegenerateFaces") << " degenerate faces, split "
              << field("SplitNonManifoldVertices") << " non-manifold vertices\n";
  }
  vtkNew<vtkMassProperties> mass;
  mass->SetInputData(mesh);
  mass->Update();
  std::cout << "area       " << mass->GetSurfaceArea() << " mm^2";
  if (repair && field("BoundaryEdges") == 0)
  {
    std::cout << ", volume " << mass->GetVolume() / 1000.0 << " ml";
  }
  std::cout << "\n";
  const std::string space = lkapp::coordinateSpace(mesh);
  std::cout << "space      "
            << (space.empty() ? "the volume's data coordinates (the file gives no orientation; no SPACE tag written)"
                              : space + " patient coordinates (tagged SPACE=" + space + ", as 3D Slicer reads it)")
            << "\n";
  std::cout << "written    " << output << written << " in " << seconds << " s\n";
  return 0;
}
