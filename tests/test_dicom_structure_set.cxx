// DICOM RT structure sets (RTSTRUCT): the organs a radiotherapy planning
// system contoured, read as segments of a label volume.
#include "DicomTestFiles.h"
#include "TestSupport.h"
#include "vtkLKBoneSurfaceFilter.h"
#include "vtkLKDICOMSeries.h" // kFoldersBesideLimit
#include "vtkLKMedicalImageReader.h"
#include "vtkLKStructureSetWriter.h"

#include <vtkAppendPolyData.h>
#include <vtkCell.h>
#include <vtkCellArray.h>
#include <vtkIdList.h>
#include <vtkCubeSource.h>
#include <vtkCylinderSource.h>
#include <vtkDICOMCompiler.h>
#include <vtkDICOMItem.h>
#include <vtkDICOMMetaData.h>
#include <vtkDICOMParser.h>
#include <vtkDICOMSequence.h>
#include <vtkDICOMUtilities.h>
#include <vtkDICOMValue.h>
#include <vtkFieldData.h>
#include <vtkFlyingEdges2D.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkMassProperties.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkStripper.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtkTriangleFilter.h>
#include <vtkXMLPolyDataReader.h>
#include <vtksys/SystemTools.hxx>

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <array>
#include <cmath>
#include <fstream>
#include <tuple>
#include <map>

namespace
{
using lktest::seriesUIDOf;
using lktest::writeCT;
using P3 = std::array<double, 3>;
using Polygon = std::vector<P3>;

struct RoiSpec
{
  int number;
  std::string name;
  std::vector<Polygon> contours;
  std::string type = "CLOSED_PLANAR";
};

/// Writes `meta` as a DICOM file with no pixel data (an RT object).
void writeDICOMObject(const std::string& file, vtkDICOMMetaData* meta)
{
  vtkNew<vtkDICOMCompiler> compiler;
  compiler->SetFileName(file.c_str());
  compiler->SetMetaData(meta);
  compiler->WriteHeader();
  compiler->Close();
  ASSERT_EQ(compiler->GetErrorCode(), 0u);
}

std::string tempFolder(const std::string& name)
{
  const std::string dir = std::string(LATTICEKIT_TEST_TMP) + "/" + name;
  vtksys::SystemTools::RemoveADirectory(dir);
  vtksys::SystemTools::MakeDirectory(dir);
  return dir;
}

/// An RT structure set as planning systems write one: the ROIs listed, each
/// one's contours, the image series they were drawn on referenced.
/// `pointCount` (when not 0) is written as every contour's
/// NumberOfContourPoints instead of the true one; `unlisted` adds contours
/// of an ROI number the list lacks; `contourText` replaces every contour's
/// ContourData; `studyUID` (when given) is the set's study and the one it
/// references, as a planning system writes a set into its CT's study;
/// `characterSet` (when given) its SpecificCharacterSet, which the ROI
/// names are then spelt in.
void writeStructureSet(const std::string& file, const std::vector<RoiSpec>& rois, const std::string& seriesUID,
  int pointCount = 0, int unlisted = 0, const char* contourText = nullptr, const std::string& studyUID = std::string(),
  const char* characterSet = nullptr)
{
  const std::string setStudy = studyUID.empty() ? vtkDICOMUtilities::GenerateUID(DC::StudyInstanceUID) : studyUID;
  vtkNew<vtkDICOMMetaData> meta;
  if (characterSet)
    meta->Set(DC::SpecificCharacterSet, characterSet);
  meta->Set(DC::SOPClassUID, "1.2.840.10008.5.1.4.1.1.481.3"); // RT Structure Set Storage
  meta->Set(DC::SOPInstanceUID, vtkDICOMUtilities::GenerateUID(DC::SOPInstanceUID));
  meta->Set(DC::StudyInstanceUID, setStudy);
  meta->Set(DC::SeriesInstanceUID, vtkDICOMUtilities::GenerateUID(DC::SeriesInstanceUID));
  meta->Set(DC::Modality, "RTSTRUCT");
  meta->Set(DC::PatientID, "rtstruct");
  meta->Set(DC::StructureSetLabel, "test");
  const std::string frameUID = vtkDICOMUtilities::GenerateUID(DC::FrameOfReferenceUID);
  vtkDICOMItem series, study, frame;
  series.Set(DC::SeriesInstanceUID, seriesUID);
  study.Set(DC::ReferencedSOPClassUID, "1.2.840.10008.3.1.2.3.1");
  study.Set(DC::ReferencedSOPInstanceUID, studyUID.empty() ? vtkDICOMUtilities::GenerateUID(DC::StudyInstanceUID) : setStudy);
  study.Set(DC::RTReferencedSeriesSequence, vtkDICOMSequence(series));
  frame.Set(DC::FrameOfReferenceUID, frameUID);
  frame.Set(DC::RTReferencedStudySequence, vtkDICOMSequence(study));
  meta->Set(DC::ReferencedFrameOfReferenceSequence, vtkDICOMSequence(frame));
  vtkDICOMSequence listed, contoured;
  for (const RoiSpec& roi : rois)
  {
    vtkDICOMItem item;
    item.Set(DC::ROINumber, static_cast<double>(roi.number));
    item.Set(DC::ReferencedFrameOfReferenceUID, frameUID);
    item.Set(DC::ROIName, roi.name);
    item.Set(DC::ROIGenerationAlgorithm, "MANUAL");
    listed.AddItem(item);
  }
  for (std::size_t r = 0; r < rois.size() + (unlisted ? 1 : 0); ++r)
  {
    const RoiSpec& roi = rois[std::min(r, rois.size() - 1)];
    vtkDICOMSequence contours;
    for (const Polygon& polygon : roi.contours)
    {
      vtkDICOMItem contour;
      std::vector<double> xyz;
      for (const P3& p : polygon)
        xyz.insert(xyz.end(), p.begin(), p.end());
      contour.Set(DC::ContourGeometricType, roi.type);
      contour.Set(DC::NumberOfContourPoints, static_cast<double>(pointCount ? pointCount : static_cast<int>(polygon.size())));
      if (contourText)
        contour.Set(DC::ContourData, vtkDICOMValue(vtkDICOMVR::DS, std::string(contourText)));
      else
        contour.Set(DC::ContourData, vtkDICOMValue(vtkDICOMVR::DS, xyz.data(), xyz.size()));
      contours.AddItem(contour);
    }
    vtkDICOMItem item;
    item.Set(DC::ReferencedROINumber, static_cast<double>(r < rois.size() ? roi.number : unlisted));
    item.Set(DC::ROIDisplayColor, "255\\0\\0");
    item.Set(DC::ContourSequence, contours);
    contoured.AddItem(item);
  }
  meta->Set(DC::StructureSetROISequence, listed);
  meta->Set(DC::ROIContourSequence, contoured);
  writeDICOMObject(file, meta);
}

/// A rectangle [x0, x1] x [y0, y1] at height z (patient mm).
Polygon rectangle(double x0, double x1, double y0, double y1, double z)
{
  return { { x0, y0, z }, { x1, y0, z }, { x1, y1, z }, { x0, y1, z } };
}

/// How many voxels of layer `layer` hold `label`.
vtkIdType count(vtkImageData* image, int layer, int label)
{
  vtkDataArray* values = image->GetPointData()->GetScalars();
  vtkIdType n = 0;
  for (vtkIdType v = 0; v < values->GetNumberOfTuples(); ++v)
    n += values->GetComponent(v, layer) == label ? 1 : 0;
  return n;
}

/// The segments in the reader's field data: name -> (label, layer).
std::map<std::string, std::pair<int, int>> segmentsOf(vtkImageData* image)
{
  auto* names = vtkStringArray::SafeDownCast(image->GetFieldData()->GetAbstractArray("SegmentNames"));
  auto* labels = vtkIntArray::SafeDownCast(image->GetFieldData()->GetArray("SegmentLabelValues"));
  auto* layers = vtkIntArray::SafeDownCast(image->GetFieldData()->GetArray("SegmentLayers"));
  std::map<std::string, std::pair<int, int>> out;
  for (vtkIdType i = 0; names && labels && layers && i < names->GetNumberOfValues(); ++i)
    out[names->GetValue(i)] = { labels->GetValue(i), layers->GetValue(i) };
  return out;
}

/// A body, a mandible inside it, a canal with a hole inside it too, and an
/// isocentre point: on the slices z = -10 + 2k of the CT of writeSmallCT,
/// their edges half-way between pixel centres (integer mm), so that how
/// many voxels each fills is known exactly.
std::vector<RoiSpec> plan()
{
  RoiSpec body{ 1, "Body", {} }, mandible{ 5, "Mandible", {} }, canal{ 3, "Canal", {} };
  for (int k = 1; k <= 10; ++k)
    body.contours.push_back(rectangle(-15.5, 15.5, -15.5, 15.5, -10 + 2 * k)); // 31 x 31 x 10 = 9610
  for (int k = 2; k <= 8; ++k)
    mandible.contours.push_back(rectangle(-10.5, -2.5, -5.5, 4.5, -10 + 2 * k)); // 8 x 10 x 7 = 560
  canal.contours.push_back(rectangle(0.5, 10.5, 0.5, 10.5, 0.0));              // 100
  Polygon hole = rectangle(3.5, 6.5, 3.5, 6.5, 0.0);                            // minus 9
  std::reverse(hole.begin(), hole.end());
  canal.contours.push_back(hole);
  RoiSpec isocentre{ 9, "Isocenter", { { { 0.0, 0.0, 0.0 } } }, "POINT" };
  return { body, mandible, canal, isocentre };
}

/// plan()'s mandible on every other of its slices (z = -6, -2, 2, 6: 4 mm
/// apart, on every other slice of writeSmallCT's CT).
RoiSpec mandibleOnEveryOtherSlice()
{
  RoiSpec mandible{ 5, "Mandible", {} };
  for (int k = 2; k <= 8; k += 2)
    mandible.contours.push_back(rectangle(-10.5, -2.5, -5.5, 4.5, -10 + 2 * k));
  return mandible;
}

/// 40 x 40 x 12 voxels of 1 x 1 x 2 mm from (-20, -20, -10), every one 0 HU,
/// its files named by `pattern` (see writeCT), in the study `studyUID` when
/// one is given, with `attributes` (see writeCT).
std::string writeSmallCT(const std::string& dir, const char* pattern = "%s/ct_%03d.dcm", const char* studyUID = nullptr,
  vtkDICOMMetaData* attributes = nullptr)
{
  vtkNew<vtkImageData> ct;
  ct->SetDimensions(40, 40, 12);
  ct->SetSpacing(1.0, 1.0, 2.0);
  ct->AllocateScalars(VTK_SHORT, 1);
  ct->GetPointData()->GetScalars()->Fill(1024.0);
  vtkNew<vtkMatrix4x4> m;
  m->SetElement(0, 3, -20.0);
  m->SetElement(1, 3, -20.0);
  m->SetElement(2, 3, -10.0);
  return writeCT(dir, ct, m, pattern, nullptr, studyUID, attributes);
}

void expectThePlansVoxels(vtkLKMedicalImageReader* reader)
{
  vtkImageData* out = reader->GetOutput();
  EXPECT_STREQ(reader->GetFileFormat(), "DICOM RTSTRUCT");
  ASSERT_EQ(out->GetNumberOfScalarComponents(), 2); // the organs overlap the body
  const auto segments = segmentsOf(out);
  ASSERT_EQ(segments.size(), 3u); // the isocentre is a point, not an organ
  EXPECT_EQ(segments.at("Body"), std::make_pair(1, 0));
  EXPECT_EQ(segments.at("Mandible"), std::make_pair(5, 1));
  EXPECT_EQ(segments.at("Canal"), std::make_pair(3, 1)); // beside the mandible: the same layer
  // The reader says the same (for scripts that list a file's organs).
  ASSERT_EQ(reader->GetNumberOfSegments(), 3);
  EXPECT_STREQ(reader->GetSegmentName(1), "Mandible");
  EXPECT_EQ(reader->GetSegmentLabelValue(1), 5);
  EXPECT_EQ(reader->GetSegmentLayer(1), 1);
  EXPECT_EQ(reader->GetSegmentName(3), nullptr);
  EXPECT_EQ(reader->GetSegmentLabelValue(-1), 0);
  EXPECT_EQ(reader->GetSegmentLayer(3), -1);
  EXPECT_EQ(count(out, 0, 1), 9610);
  EXPECT_EQ(count(out, 1, 5), 560);
  EXPECT_EQ(count(out, 1, 3), 91); // the inner contour is a hole
  double spacing[3];
  out->GetSpacing(spacing);
  EXPECT_DOUBLE_EQ(spacing[0], 1.0);
  EXPECT_DOUBLE_EQ(spacing[1], 1.0);
  EXPECT_DOUBLE_EQ(spacing[2], 2.0);
  // Voxel centres on the pixel centres (integer mm) and the slices (-10 + 2k).
  vtkMatrix4x4* m = reader->GetPatientMatrix();
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      EXPECT_NEAR(std::abs(m->GetElement(a, b)), a == b ? 1.0 : 0.0, 1e-9);
  EXPECT_NEAR(m->GetElement(0, 3), std::round(m->GetElement(0, 3)), 1e-6);
  EXPECT_NEAR(m->GetElement(1, 3), std::round(m->GetElement(1, 3)), 1e-6);
  EXPECT_NEAR(std::remainder(m->GetElement(2, 3) + 10.0, 2.0), 0.0, 1e-6);
  // The mandible's voxels lie where its contours are: its centre (-6.5, -0.5, 0).
  double centre[3] = { 0, 0, 0 };
  int n = 0;
  int dims[3];
  out->GetDimensions(dims);
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i)
        if (out->GetScalarComponentAsDouble(i, j, k, 1) == 5)
        {
          const double p[4] = { i * spacing[0], j * spacing[1], k * spacing[2], 1.0 };
          double q[4];
          m->MultiplyPoint(p, q);
          for (int a = 0; a < 3; ++a)
            centre[a] += q[a];
          ++n;
        }
  ASSERT_GT(n, 0);
  EXPECT_NEAR(centre[0] / n, -6.5, 1e-6);
  EXPECT_NEAR(centre[1] / n, -0.5, 1e-6);
  EXPECT_NEAR(centre[2] / n, 0.0, 1e-6);
}
} // namespace

TEST(DicomStructureSet, ROIsAreFilledOnTheGridOfTheCTBesideThem)
{
  const std::string dir = tempFolder("rtstruct_with_ct");
  const std::string uid = writeSmallCT(dir);
  ASSERT_FALSE(uid.empty());
  const std::string file = dir + "/rtstruct.dcm";
  writeStructureSet(file, plan(), uid);
  vtkNew<vtkLKMedicalImageReader> reader;
  lktest::ErrorRecorder rec(reader);
  reader->SetFileName(file.c_str());
  reader->Update();
  ASSERT_EQ(rec.errors, 0) << rec.messages;
  expectThePlansVoxels(reader);
  // What is made from its ROIs goes back to this CT (the structure set
  // writer's ReferenceFileName).
  EXPECT_EQ(seriesUIDOf(reader->GetReferenceImageFileName()), uid);
  // Only the isocentre is worth a word: the grid is the CT's.
  EXPECT_EQ(rec.warnings, 1) << rec.warningMessages;
  EXPECT_NE(rec.warningMessages.find("ROIs without closed planar contours are not read: 'Isocenter' (POINT)"),
    std::string::npos)
    << rec.warningMessages;

  // The folder, or a file of the CT, reads the CT, and says how to read the
  // structure set beside it.
  for (const std::string& input : { dir, dir + "/ct_001.dcm" })
  {
    vtkNew<vtkLKMedicalImageReader> ctReader;
    lktest::ErrorRecorder ctRec(ctReader);
    ctReader->SetFileName(input.c_str());
    ctReader->Update();
    EXPECT_EQ(ctRec.errors, 0) << ctRec.messages;
    EXPECT_STREQ(ctReader->GetFileFormat(), "DICOM");
    EXPECT_EQ(seriesUIDOf(ctReader->GetReferenceImageFileName()), uid);
    EXPECT_EQ(ctReader->GetOutput()->GetNumberOfScalarComponents(), 1);
    EXPECT_EQ(ctRec.warnings, 1) << ctRec.warningMessages;
    EXPECT_NE(ctRec.warningMessages.find("The folder also holds an RT structure set (organs contoured for "
                                         "radiotherapy); give its file to read its ROIs as segments (latticekit-surface and the "
                                         "planner do when --label names one of them):\n  '" +
                file + "', drawn on this series: 'Body', 'Mandible', 'Canal', 'Isocenter'"),
      std::string::npos)
      << ctRec.warningMessages;
    // The same, for scripts: the sets drawn on this CT, and their ROIs.
    ASSERT_EQ(ctReader->GetNumberOfStructureSets(), 1);
    EXPECT_EQ(std::string(ctReader->GetStructureSetFileName(0)), file);
    ASSERT_EQ(ctReader->GetNumberOfStructureSetROIs(0), 4);
    EXPECT_STREQ(ctReader->GetStructureSetROIName(0, 1), "Mandible");
    EXPECT_EQ(ctReader->GetStructureSetROIName(0, 4), nullptr);
    EXPECT_EQ(ctReader->GetStructureSetFileName(1), nullptr);
    EXPECT_EQ(ctReader->GetNumberOfStructureSetROIs(-1), 0);
  }
}

TEST(DicomStructureSet, AnROIOnEveryOtherSliceOfItsCTIsInterpolatedOnTheCTsSlices)
{
  // The mandible alone, on every other slice of the CT (4 mm apart): with
  // the CT beside it, the grid has the CT's 2 mm slices and the 3 between
  // are interpolated (560 voxels, as on every slice); without it, the grid
  // is the contours' own, 4 mm slices (320 voxels).
  const RoiSpec mandible = mandibleOnEveryOtherSlice();
  // Alone: one folder further down than a folder beside the CT's would be.
  const std::string withCT = tempFolder("rtstruct_sparse_with_ct"), alone = tempFolder("rtstruct_sparse_alone") + "/rs";
  vtksys::SystemTools::MakeDirectory(alone);
  const std::string uid = writeSmallCT(withCT);
  writeStructureSet(withCT + "/rs.dcm", { mandible }, uid);
  writeStructureSet(alone + "/rs.dcm", { mandible }, uid);
  for (const std::string& dir : { withCT, alone })
  {
    vtkNew<vtkLKMedicalImageReader> reader;
    lktest::ErrorRecorder rec(reader);
    reader->SetFileName((dir + "/rs.dcm").c_str());
    reader->Update();
    ASSERT_EQ(rec.errors, 0) << rec.messages;
    double spacing[3];
    reader->GetOutput()->GetSpacing(spacing);
    const bool ct = dir == withCT;
    EXPECT_DOUBLE_EQ(spacing[2], ct ? 2.0 : 4.0);
    EXPECT_EQ(count(reader->GetOutput(), 0, 5), ct ? 560 : 320);
    EXPECT_EQ(rec.warnings, 1) << rec.warningMessages;
    EXPECT_NE(rec.warningMessages.find(ct ? "ROI 'Mandible' has no contour on 3 of the slices between its first and "
                                            "last (2 mm apart): they are filled by interpolating"
                                          : "is neither in its folder nor in a folder beside it"),
      std::string::npos)
      << rec.warningMessages;
  }
}

// A study exported one series to a folder (as TCIA, PACS and 3D Slicer
// exports lie): the structure set finds its CT in the folder beside its
// own, and the CT its structure set; not a set drawn on another series.
TEST(DicomStructureSet, ASetAndItsCTInFoldersSideBySideFindEachOther)
{
  const RoiSpec mandible = mandibleOnEveryOtherSlice();
  const std::string study = tempFolder("rtstruct_study");
  for (const char* folder : { "/0-pipe", "/1-CT", "/2-CT-other", "/3-RTSTRUCT", "/4-docs" })
    vtksys::SystemTools::MakeDirectory(study + folder);
  std::ofstream(study + "/4-docs/LICENSE") << "not DICOM\n";
  // A named pipe is not opened (it would wait for a writer for ever).
  ASSERT_EQ(mkfifo((study + "/0-pipe/fifo").c_str(), 0600), 0);
  const std::string uid = writeSmallCT(study + "/1-CT");
  const std::string otherUid = writeSmallCT(study + "/2-CT-other");
  ASSERT_NE(uid, otherUid);
  const std::string set = study + "/3-RTSTRUCT/rs.dcm";
  writeStructureSet(set, { mandible }, uid);

  vtkNew<vtkLKMedicalImageReader> reader;
  lktest::ErrorRecorder rec(reader);
  reader->SetFileName(set.c_str());
  reader->Update();
  ASSERT_EQ(rec.errors, 0) << rec.messages;
  // The CT's 2 mm slices, with the slices between contours interpolated.
  EXPECT_DOUBLE_EQ(reader->GetOutput()->GetSpacing()[2], 2.0);
  EXPECT_EQ(count(reader->GetOutput(), 0, 5), 560);
  EXPECT_EQ(vtksys::SystemTools::GetFilenamePath(reader->GetReferenceImageFileName()), study + "/1-CT");
  EXPECT_EQ(rec.warningMessages.find("grid of their own"), std::string::npos) << rec.warningMessages;

  vtkNew<vtkLKMedicalImageReader> ctReader;
  lktest::ErrorRecorder ctRec(ctReader);
  ctReader->SetFileName((study + "/1-CT").c_str());
  ctReader->Update();
  ASSERT_EQ(ctRec.errors, 0) << ctRec.messages;
  ASSERT_EQ(ctReader->GetNumberOfStructureSets(), 1);
  EXPECT_EQ(std::string(ctReader->GetStructureSetFileName(0)), set);
  EXPECT_STREQ(ctReader->GetStructureSetROIName(0, 0), "Mandible");
  EXPECT_NE(ctRec.warningMessages.find("A folder beside the CT's holds an RT structure set (organs contoured for "
                                       "radiotherapy); give its file"),
    std::string::npos)
    << ctRec.warningMessages;

  // The other CT of the study: the set is not drawn on it.
  vtkNew<vtkLKMedicalImageReader> otherReader;
  lktest::ErrorRecorder otherRec(otherReader);
  otherReader->SetFileName((study + "/2-CT-other").c_str());
  otherReader->Update();
  ASSERT_EQ(otherRec.errors, 0) << otherRec.messages;
  EXPECT_EQ(otherReader->GetNumberOfStructureSets(), 0);
  EXPECT_EQ(otherRec.warningMessages.find("structure set"), std::string::npos) << otherRec.warningMessages;

  // A folder of more folders than a study has series (a disk's, a home's)
  // is not searched: the set alone there makes its own grid.
  const std::string crowded = tempFolder("rtstruct_crowded");
  for (int f = 0; f <= lkvtk::kFoldersBesideLimit; ++f)
    vtksys::SystemTools::MakeDirectory(crowded + "/empty" + std::to_string(f));
  vtksys::SystemTools::MakeDirectory(crowded + "/CT");
  vtksys::SystemTools::MakeDirectory(crowded + "/RTSTRUCT");
  writeStructureSet(crowded + "/RTSTRUCT/rs.dcm", { mandible }, writeSmallCT(crowded + "/CT"));
  vtkNew<vtkLKMedicalImageReader> crowdedReader;
  lktest::ErrorRecorder crowdedRec(crowdedReader);
  crowdedReader->SetFileName((crowded + "/RTSTRUCT/rs.dcm").c_str());
  crowdedReader->Update();
  ASSERT_EQ(crowdedRec.errors, 0) << crowdedRec.messages;
  EXPECT_DOUBLE_EQ(crowdedReader->GetOutput()->GetSpacing()[2], 4.0);
  EXPECT_STREQ(crowdedReader->GetReferenceImageFileName(), "");
  EXPECT_NE(crowdedRec.warningMessages.find("is not in its folder, and the folders beside it were not searched "
                                            "(over 256 of them: not a study's): its ROIs are filled on a grid of "
                                            "their own"),
    std::string::npos)
    << crowdedRec.warningMessages;
}

TEST(DicomStructureSet, ASetAndItsCTInFoldersThatHoldOtherSeriesFirstFindEachOther)
{
  // A study exported with its images in one folder and its RT objects in
  // another: a scout series' files come first in the one, a dose's in the
  // other, so neither folder's first file is what is looked for.
  const RoiSpec mandible = mandibleOnEveryOtherSlice();
  const std::string study = tempFolder("rtstruct_mixed");
  vtksys::SystemTools::MakeDirectory(study + "/IMAGES");
  vtksys::SystemTools::MakeDirectory(study + "/RT");
  vtksys::SystemTools::MakeDirectory(study + "/OTHER");
  const std::string studyUID = vtkDICOMUtilities::GenerateUID(DC::StudyInstanceUID);
  const std::string scoutUID = writeSmallCT(study + "/IMAGES", "%s/a_scout_%03d.dcm", studyUID.c_str());
  const std::string uid = writeSmallCT(study + "/IMAGES", "%s/ct_%03d.dcm", studyUID.c_str());
  ASSERT_NE(scoutUID, uid);
  // Another study's folder: not searched beyond its first file.
  writeSmallCT(study + "/OTHER", "%s/a_%03d.dcm");
  writeStructureSet(study + "/OTHER/rs.dcm", { mandible }, uid);
  {
    vtkNew<vtkDICOMMetaData> dose;
    dose->Set(DC::SOPClassUID, "1.2.840.10008.5.1.4.1.1.481.2"); // RT Dose Storage
    dose->Set(DC::SOPInstanceUID, vtkDICOMUtilities::GenerateUID(DC::SOPInstanceUID));
    dose->Set(DC::StudyInstanceUID, studyUID);
    dose->Set(DC::SeriesInstanceUID, vtkDICOMUtilities::GenerateUID(DC::SeriesInstanceUID));
    dose->Set(DC::Modality, "RTDOSE");
    writeDICOMObject(study + "/RT/RD.dcm", dose);
  }
  const std::string set = study + "/RT/RS.dcm";
  writeStructureSet(set, { mandible }, uid, 0, 0, nullptr, studyUID);

  vtkNew<vtkLKMedicalImageReader> reader;
  lktest::ErrorRecorder rec(reader);
  reader->SetFileName(set.c_str());
  reader->Update();
  ASSERT_EQ(rec.errors, 0) << rec.messages;
  EXPECT_DOUBLE_EQ(reader->GetOutput()->GetSpacing()[2], 2.0); // the CT's slices
  EXPECT_EQ(count(reader->GetOutput(), 0, 5), 560);
  EXPECT_EQ(seriesUIDOf(reader->GetReferenceImageFileName()), uid);
  EXPECT_EQ(rec.warningMessages.find("grid of their own"), std::string::npos) << rec.warningMessages;

  // The CT, by one of its files, finds the set among the study's RT
  // objects, and not the other study's.
  vtkNew<vtkLKMedicalImageReader> ctReader;
  lktest::ErrorRecorder ctRec(ctReader);
  ctReader->SetFileName((study + "/IMAGES/ct_001.dcm").c_str());
  ctReader->Update();
  ASSERT_EQ(ctRec.errors, 0) << ctRec.messages;
  ASSERT_EQ(ctReader->GetNumberOfStructureSets(), 1) << ctRec.warningMessages;
  EXPECT_EQ(std::string(ctReader->GetStructureSetFileName(0)), set);
  EXPECT_STREQ(ctReader->GetStructureSetROIName(0, 0), "Mandible");
}

TEST(DicomStructureSet, WithoutItsCTTheContoursMakeTheirOwnGrid)
{
  const std::string dir = tempFolder("rtstruct_alone");
  const std::string file = dir + "/rtstruct.dcm";
  writeStructureSet(file, plan(), "1.2.3.4.5.6.7.8.9");
  vtkNew<vtkLKMedicalImageReader> reader;
  lktest::ErrorRecorder rec(reader);
  reader->SetFileName(file.c_str());
  reader->Update();
  ASSERT_EQ(rec.errors, 0) << rec.messages;
  expectThePlansVoxels(reader); // axial contours: an axial grid of 1 mm pixels and their 2 mm slices
  EXPECT_STREQ(reader->GetReferenceImageFileName(), ""); // no CT to go back to
  EXPECT_NE(rec.warningMessages.find("the image series the structure set was drawn on (1.2.3.4.5.6.7.8.9) is neither "
                                     "in its folder nor in a folder beside it: its ROIs are filled on a grid of their "
                                     "own, 1 mm pixels and 2 mm slices"),
    std::string::npos)
    << rec.warningMessages;

  // The bone surface filter takes an organ by name, in patient space.
  vtkNew<vtkLKBoneSurfaceFilter> bone;
  lktest::ErrorRecorder boneRec(bone);
  bone->SetInputConnection(reader->GetOutputPort());
  bone->SetLabelName("Mandible");
  bone->Update();
  ASSERT_EQ(boneRec.errors, 0) << boneRec.messages;
  EXPECT_EQ(bone->GetEffectiveLabel(), 5);
  double b[6];
  bone->GetOutput()->GetBounds(b);
  EXPECT_NEAR(0.5 * (b[0] + b[1]), -6.5, 0.5);
  EXPECT_NEAR(0.5 * (b[2] + b[3]), -0.5, 0.5);
  EXPECT_NEAR(0.5 * (b[4] + b[5]), 0.0, 0.5);
  EXPECT_GT(b[1] - b[0], 6.0);
  EXPECT_LT(b[1] - b[0], 10.0);
}

/// The rectangle [x0, x1] x [y0, y1] at height z with a point every 0.4 mm
/// along its sides, as a contour traced on a 0.5 mm CT.
Polygon densely(double x0, double x1, double y0, double y1, double z)
{
  Polygon polygon;
  const double step = 0.4;
  const P3 corners[4] = { { x0, y0, z }, { x1, y0, z }, { x1, y1, z }, { x0, y1, z } };
  for (int k = 0; k < 4; ++k)
  {
    const P3& a = corners[k];
    const P3& b = corners[(k + 1) % 4];
    const double length = std::hypot(b[0] - a[0], b[1] - a[1]);
    const int n = static_cast<int>(std::ceil(length / step - 1e-9));
    for (int i = 0; i < n; ++i)
      polygon.push_back({ a[0] + (b[0] - a[0]) * i / n, a[1] + (b[1] - a[1]) * i / n, z });
  }
  return polygon;
}

TEST(DicomStructureSet, WithoutItsCTFineContoursGetFinerPixels)
{
  // A wall 0.8 mm thin, contoured with a point every 0.4 mm (as a contour
  // drawn on a 0.5 mm CT is): on 1 mm pixels no pixel centre lies inside
  // it, and it would vanish. Its grid gets 0.5 mm pixels.
  RoiSpec wall{ 1, "Orbital wall", {} };
  for (double z : { 0.0, 2.0, 4.0 })
    wall.contours.push_back(densely(0.1, 0.9, 0.1, 19.9, z));
  const std::string dir = tempFolder("rtstruct_fine");
  writeStructureSet(dir + "/rs.dcm", { wall }, "1.2.3.4.5.6.7.8.10");
  vtkNew<vtkLKMedicalImageReader> reader;
  lktest::ErrorRecorder rec(reader);
  reader->SetFileName((dir + "/rs.dcm").c_str());
  reader->Update();
  ASSERT_EQ(rec.errors, 0) << rec.messages;
  EXPECT_DOUBLE_EQ(reader->GetOutput()->GetSpacing()[0], 0.5);
  EXPECT_DOUBLE_EQ(reader->GetOutput()->GetSpacing()[2], 2.0);
  // One column of pixel centres (x = 0.5), 39 rows (y = 0.5 to 19.5), 3 slices.
  EXPECT_EQ(count(reader->GetOutput(), 0, 1), 117);
  EXPECT_NE(rec.warningMessages.find("its ROIs are filled on a grid of their own, 0.5 mm pixels and 2 mm slices"),
    std::string::npos)
    << rec.warningMessages;

  // The same wall among 14 ROIs over 2.5 m: 0.5 mm pixels would be 7.5e7
  // voxels, over 1e9 for 14 layers, so the pixels stay 1 mm.
  RoiSpec body{ 2, "Body", {} };
  std::vector<RoiSpec> many{ wall, body };
  for (double z : { 0.0, 2.0, 4.0 })
    many[1].contours.push_back(rectangle(-1250.0, 1250.0, -1250.0, 1250.0, z));
  for (int r = 0; r < 12; ++r)
    many.push_back({ 3 + r, "Marker " + std::to_string(r), { rectangle(-1000.0 + 20 * r, -995.0 + 20 * r, 0, 5, 0) } });
  writeStructureSet(dir + "/many.dcm", many, "1.2.3.4.5.6.7.8.10");
  vtkNew<vtkLKMedicalImageReader> manyReader;
  lktest::ErrorRecorder manyRec(manyReader);
  manyReader->SetFileName((dir + "/many.dcm").c_str());
  manyReader->Update();
  ASSERT_EQ(manyRec.errors, 0) << manyRec.messages;
  EXPECT_DOUBLE_EQ(manyReader->GetOutput()->GetSpacing()[0], 1.0);
}

TEST(DicomStructureSet, SlicesBetweenContoursAreInterpolatedAndUnevenPlanesWarned)
{
  // The parotid contoured every 2 mm, a node 1 mm above it and once more
  // 2.9 mm higher: the slices are 1 mm apart (the smallest gap), so the
  // parotid skips every other one and the node two; the node's second plane
  // is moved 0.1 mm. A cord contoured on every slice but for a gap of 5
  // slices, which is not bridged; a tumour that widens from 10 to 20 mm over
  // one skipped slice.
  const std::string dir = tempFolder("rtstruct_uneven");
  RoiSpec parotid{ 1, "Parotid", {} };
  for (int k : { 0, 2, 4, 6 })
    parotid.contours.push_back(rectangle(0.5, 5.5, 0.5, 5.5, k));
  RoiSpec node{ 2, "Node", { rectangle(20.5, 25.5, 0.5, 5.5, 7.0), rectangle(20.5, 25.5, 0.5, 5.5, 9.9) } };
  RoiSpec cord{ 3, "Cord", {} };
  for (int k : { 20, 21, 22, 23, 29, 30 })
    cord.contours.push_back(rectangle(-20.5, -15.5, 0.5, 5.5, k));
  RoiSpec tumour{ 4, "Tumour", { rectangle(0.5, 10.5, 20.5, 30.5, 0.0), rectangle(0.5, 20.5, 20.5, 30.5, 2.0) } };
  writeStructureSet(dir + "/rs.dcm", { parotid, node, cord, tumour }, "1.2.3");
  vtkNew<vtkLKMedicalImageReader> reader;
  lktest::ErrorRecorder rec(reader);
  reader->SetFileName((dir + "/rs.dcm").c_str());
  reader->Update();
  ASSERT_EQ(rec.errors, 0) << rec.messages;
  const std::string& w = rec.warningMessages;
  EXPECT_NE(w.find("the contours' planes are not evenly spaced: some were moved up to 0.1 mm onto the slices of 1 mm"),
    std::string::npos)
    << w;
  EXPECT_NE(w.find("ROI 'Parotid' has no contour on 3 of the slices between its first and last (1 mm apart): they "
                   "are filled by interpolating the contours on either side"),
    std::string::npos)
    << w;
  EXPECT_NE(w.find("ROI 'Node' has no contour on 2 of the slices between its first and last (1 mm apart): they are "
                   "filled"),
    std::string::npos)
    << w;
  EXPECT_NE(w.find("ROI 'Cord' has no contour on 5 of the slices between its first and last (1 mm apart): its "
                   "surface has gaps there (each over twice its usual contour spacing, not bridged)"),
    std::string::npos)
    << w;
  vtkImageData* out = reader->GetOutput();
  EXPECT_EQ(out->GetNumberOfScalarComponents(), 1); // apart: one layer
  EXPECT_EQ(count(out, 0, 1), 7 * 25);              // a square on every slice from 0 to 6 mm
  EXPECT_EQ(count(out, 0, 2), 4 * 25);
  EXPECT_EQ(count(out, 0, 3), 6 * 25);
  // The tumour's middle slice lies between its two rectangles: 10 to 15 mm
  // wide (the corners of the widening are rounded).
  const vtkIdType middle = count(out, 0, 4) - 100 - 200;
  EXPECT_GT(middle, 100);
  EXPECT_LE(middle, 150);
  double spacing[3];
  out->GetSpacing(spacing);
  EXPECT_DOUBLE_EQ(spacing[2], 1.0);
}

TEST(DicomStructureSet, TwoROIsOfOneNameAreWarnedOf)
{
  // An organ twice (as drawn and as edited): by name the first is taken,
  // with a warning naming the other's label; by label the other.
  const std::string dir = tempFolder("rtstruct_same_name");
  writeStructureSet(dir + "/rs.dcm",
    { { 3, "Mandible", { rectangle(0.5, 5.5, 0.5, 5.5, 0.0), rectangle(0.5, 5.5, 0.5, 5.5, 2.0) } },
      { 8, "mandible", { rectangle(2.5, 9.5, 0.5, 5.5, 0.0), rectangle(2.5, 9.5, 0.5, 5.5, 2.0) } } },
    "1.2.3");
  vtkNew<vtkLKMedicalImageReader> reader;
  reader->SetFileName((dir + "/rs.dcm").c_str());
  lktest::ErrorRecorder quiet(reader); // its warnings: no CT beside it
  vtkNew<vtkLKBoneSurfaceFilter> bone;
  lktest::ErrorRecorder rec(bone);
  bone->SetInputConnection(reader->GetOutputPort());
  bone->SetLabelName("Mandible");
  bone->Update();
  EXPECT_EQ(rec.errors, 0) << rec.messages;
  EXPECT_EQ(bone->GetEffectiveLabel(), 3);
  EXPECT_NE(rec.warningMessages.find("More than one segment is named 'Mandible': the first, label 3 (layer 0), is "
                                     "taken; the others have the labels 8 (layer 1)"),
    std::string::npos)
    << rec.warningMessages;
  bone->SetLabelName(nullptr);
  bone->SetLabel(8);
  bone->Update();
  EXPECT_EQ(rec.errors, 0) << rec.messages;
  EXPECT_STREQ(bone->GetEffectiveSegmentName(), "mandible");
}

TEST(DicomStructureSet, ReadingReportsProgressAndStopsWithNoVolumeAndNoSegments)
{
  // tests/data/rtstruct/head_and_neck.dcm: a body, a mandible, a cord, a point.
  vtkNew<vtkLKMedicalImageReader> reader;
  reader->SetFileName((std::string(LATTICEKIT_TEST_DATA) + "/rtstruct/head_and_neck.dcm").c_str());
  lktest::ErrorRecorder rec(reader);
  {
    lktest::ProgressRecorder progress(reader);
    reader->Update();
    EXPECT_GE(std::count_if(progress.progress.begin(), progress.progress.end(), [](double p) { return p > 0.0 && p < 1.0; }),
      3);
  }
  ASSERT_EQ(rec.errors, 0) << rec.messages;
  EXPECT_EQ(reader->GetNumberOfSegments(), 3);
  {
    lktest::ProgressRecorder progress(reader);
    progress.stopAt = 0.5; // after the first ROIs
    reader->Modified();
    reader->Update();
  }
  EXPECT_EQ(rec.errors, 0) << rec.messages;
  EXPECT_NE(rec.warningMessages.find("Aborted."), std::string::npos) << rec.warningMessages;
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(reader->GetNumberOfSegments(), 0);
  reader->Modified();
  reader->Update();
  EXPECT_EQ(rec.errors, 0) << rec.messages;
  EXPECT_EQ(reader->GetNumberOfSegments(), 3);
  EXPECT_GT(reader->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(DicomStructureSet, BrokenStructureSetsAreClearErrors)
{
  const std::string dir = tempFolder("rtstruct_broken");
  auto read = [&](const std::string& file, std::string& messages) {
    vtkNew<vtkLKMedicalImageReader> reader;
    lktest::ErrorRecorder rec(reader);
    reader->SetFileName(file.c_str());
    reader->Update();
    messages = rec.messages;
    EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
    return rec.errors;
  };
  std::string messages;

  // Only a point: nothing to fill.
  writeStructureSet(dir + "/point.dcm", { { 9, "Isocenter", { { { 0.0, 0.0, 0.0 } } }, "POINT" } }, "1.2.3");
  EXPECT_EQ(read(dir + "/point.dcm", messages), 1);
  EXPECT_NE(messages.find("no ROI of the RT structure set has closed planar contours: 'Isocenter' (POINT)"),
    std::string::npos)
    << messages;

  // NumberOfContourPoints that does not match ContourData.
  writeStructureSet(dir + "/count.dcm", { { 1, "Body", { rectangle(0, 5, 0, 5, 0) } } }, "1.2.3", 5);
  EXPECT_EQ(read(dir + "/count.dcm", messages), 1);
  EXPECT_NE(messages.find("a contour of ROI 'Body' has 12 ContourData values, which is not three per point of its "
                          "NumberOfContourPoints (5)"),
    std::string::npos)
    << messages;

  // Contours of an ROI the list lacks.
  writeStructureSet(dir + "/unlisted.dcm", { { 1, "Body", { rectangle(0, 5, 0, 5, 0) } } }, "1.2.3", 0, 7);
  EXPECT_EQ(read(dir + "/unlisted.dcm", messages), 1);
  EXPECT_NE(messages.find("contours of ROI 7, which its StructureSetROISequence does not list"), std::string::npos)
    << messages;

  // An axial contour and a sagittal one.
  writeStructureSet(dir + "/crossed.dcm",
    { { 1, "Body", { rectangle(0, 5, 0, 5, 0) } }, { 2, "Cut", { { { 1, 0, 0 }, { 1, 5, 0 }, { 1, 5, 5 }, { 1, 0, 5 } } } } },
    "1.2.3");
  EXPECT_EQ(read(dir + "/crossed.dcm", messages), 1);
  EXPECT_NE(messages.find("the contours of the RT structure set do not lie in parallel planes"), std::string::npos)
    << messages;

  // A contour whose points are all on a line encloses nothing.
  writeStructureSet(dir + "/flat.dcm", { { 1, "Body", { { { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 } } } } }, "1.2.3");
  EXPECT_EQ(read(dir + "/flat.dcm", messages), 1);
  EXPECT_NE(messages.find("the contours of the RT structure set enclose no area"), std::string::npos) << messages;

  // A coordinate that is not a number (vtkDICOMValue reads "nan" as 0).
  writeStructureSet(dir + "/nan.dcm", { { 1, "Body", { rectangle(0, 5, 0, 5, 0) } } }, "1.2.3", 0, 0, "0\\0\\0\\5\\0\\0\\5\\nan\\0\\0\\5\\0");
  EXPECT_EQ(read(dir + "/nan.dcm", messages), 1);
  EXPECT_NE(messages.find("a contour of ROI 'Body' has a coordinate that is not a number"), std::string::npos)
    << messages;

  // A contour 18 m across: a volume that does not fit.
  writeStructureSet(dir + "/huge.dcm",
    { { 1, "Body", { rectangle(0, 5, 0, 5, 0), rectangle(-9000, 9000, -9000, 9000, 2) } } }, "1.2.3");
  EXPECT_EQ(read(dir + "/huge.dcm", messages), 1);
  EXPECT_NE(messages.find("the contours of the RT structure set span 18000 mm by 18000 mm by 2 mm: too large a "
                          "volume at 1 mm pixels and 2 mm slices"),
    std::string::npos)
    << messages;
  // Planes 0.06 mm apart and 9 m away: too many slices.
  writeStructureSet(dir + "/tall.dcm",
    { { 1, "Body", { rectangle(0, 5, 0, 5, 0), rectangle(0, 5, 0, 5, 0.06), rectangle(0, 5, 0, 5, 9000) } } }, "1.2.3");
  EXPECT_EQ(read(dir + "/tall.dcm", messages), 1);
  EXPECT_NE(messages.find("the contours of the RT structure set span 9000 mm across their planes, too many slices of "
                          "0.06 mm"),
    std::string::npos)
    << messages;
  // A point a kilometre away: damage, not anatomy.
  writeStructureSet(dir + "/far.dcm", { { 1, "Body", { rectangle(0, 5, 0, 1e6, 0) } } }, "1.2.3");
  EXPECT_EQ(read(dir + "/far.dcm", messages), 1);
  EXPECT_NE(messages.find("a contour of ROI 'Body' has a point at 1e+06 mm: no patient reaches that far from the "
                          "scanner's origin"),
    std::string::npos)
    << messages;

  // Not a sequence where the ROIs should be (a damaged file): no ROIs, not a crash.
  {
    vtkNew<vtkDICOMMetaData> meta;
    meta->Set(DC::SOPClassUID, "1.2.840.10008.5.1.4.1.1.481.3");
    meta->Set(DC::Modality, "RTSTRUCT");
    meta->Set(DC::StructureSetROISequence, vtkDICOMValue(vtkDICOMVR::LO, "Body"));
    writeDICOMObject(dir + "/notasequence.dcm", meta);
  }
  EXPECT_EQ(read(dir + "/notasequence.dcm", messages), 1);
  EXPECT_NE(messages.find("the RT structure set lists no ROIs (StructureSetROISequence)"), std::string::npos)
    << messages;

  // Cut short: the file ends inside its contours.
  writeStructureSet(dir + "/whole.dcm", plan(), "1.2.3");
  std::string bytes;
  {
    std::ifstream in(dir + "/whole.dcm", std::ios::binary);
    bytes.assign(std::istreambuf_iterator<char>(in), {});
  }
  std::ofstream(dir + "/short.dcm", std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size() * 2 / 3));
  EXPECT_EQ(read(dir + "/short.dcm", messages), 1);
  EXPECT_NE(messages.find("cannot read the DICOM file"), std::string::npos) << messages;
}

TEST(DicomStructureSet, AMandibleContouredSliceBySliceIsItsLabelMapAgain)
{
  // The TCIA mandible's label map, written as a CT (cropped), and its
  // outline on every slice (VTK's flying edges at 0.5) written as the
  // contours of an RT structure set drawn on that CT, as a planning system
  // exports an organ it segmented: read back, the contours fill exactly the
  // voxels of the label map.
  vtkNew<vtkLKMedicalImageReader> nrrd;
  nrrd->SetFileName(lktest::sampleData("mandible-tcia/test_oncologist_0522c0017_Mandible.nrrd").c_str());
  nrrd->Update();
  vtkImageData* label = nrrd->GetOutput();
  int dims[3];
  double spacing[3];
  label->GetDimensions(dims);
  label->GetSpacing(spacing);
  int lo[3] = { dims[0], dims[1], dims[2] }, hi[3] = { -1, -1, -1 };
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i)
        if (label->GetScalarComponentAsDouble(i, j, k, 0) > 0.0)
        {
          const int at[3] = { i, j, k };
          for (int a = 0; a < 3; ++a)
          {
            lo[a] = std::min(lo[a], at[a]);
            hi[a] = std::max(hi[a], at[a]);
          }
        }
  ASSERT_GE(hi[0], lo[0]);
  for (int a = 0; a < 3; ++a)
  {
    lo[a] = std::max(0, lo[a] - 3);
    hi[a] = std::min(dims[a] - 1, hi[a] + 3);
  }
  vtkNew<vtkImageData> ct;
  const int n[3] = { hi[0] - lo[0] + 1, hi[1] - lo[1] + 1, hi[2] - lo[2] + 1 };
  ct->SetDimensions(n[0], n[1], n[2]);
  ct->SetSpacing(spacing);
  ct->AllocateScalars(VTK_SHORT, 1);
  vtkIdType inside = 0;
  for (int k = 0; k < n[2]; ++k)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i)
      {
        const bool in = label->GetScalarComponentAsDouble(lo[0] + i, lo[1] + j, lo[2] + k, 0) > 0.0;
        ct->SetScalarComponentFromDouble(i, j, k, 0, in ? 1000.0 : 0.0);
        inside += in ? 1 : 0;
      }
  vtkNew<vtkMatrix4x4> shift, matrix;
  for (int a = 0; a < 3; ++a)
    shift->SetElement(a, 3, lo[a] * spacing[a]);
  vtkMatrix4x4::Multiply4x4(nrrd->GetPatientMatrix(), shift, matrix);
  const std::string dir = tempFolder("rtstruct_mandible");
  const std::string uid = writeCT(dir, ct, matrix);

  RoiSpec mandible{ 1, "Mandible", {} };
  std::vector<int> contourSlice; // of each of the mandible's contours
  for (int k = 0; k < n[2]; ++k)
  {
    vtkNew<vtkImageData> slice;
    slice->SetDimensions(n[0], n[1], 1);
    slice->SetSpacing(spacing);
    slice->AllocateScalars(VTK_SHORT, 1);
    std::copy_n(static_cast<short*>(ct->GetScalarPointer(0, 0, k)), n[0] * n[1],
      static_cast<short*>(slice->GetScalarPointer()));
    vtkNew<vtkFlyingEdges2D> outline;
    outline->SetInputData(slice);
    outline->SetValue(0, 500.0);
    vtkNew<vtkStripper> loops;
    loops->SetInputConnection(outline->GetOutputPort());
    loops->Update();
    vtkPolyData* lines = loops->GetOutput();
    vtkIdType count = 0;
    const vtkIdType* ids = nullptr;
    for (vtkIdType c = 0; c < lines->GetNumberOfCells(); ++c)
    {
      lines->GetLines()->GetCellAtId(c, count, ids);
      ASSERT_EQ(ids[0], ids[count - 1]) << "an open outline on slice " << k;
      Polygon polygon;
      for (vtkIdType p = 0; p + 1 < count; ++p)
      {
        double x[4] = { 0, 0, k * spacing[2], 1.0 }, y[4];
        lines->GetPoint(ids[p], x);
        x[2] = k * spacing[2];
        x[3] = 1.0;
        matrix->MultiplyPoint(x, y);
        polygon.push_back({ y[0], y[1], y[2] });
      }
      mandible.contours.push_back(polygon);
      contourSlice.push_back(k);
    }
  }
  ASSERT_GT(mandible.contours.size(), 20u);
  writeStructureSet(dir + "/rtstruct.dcm", { mandible }, uid);

  vtkNew<vtkLKMedicalImageReader> reader;
  lktest::ErrorRecorder rec(reader);
  reader->SetFileName((dir + "/rtstruct.dcm").c_str());
  reader->Update();
  ASSERT_EQ(rec.errors, 0) << rec.messages;
  EXPECT_EQ(rec.warnings, 0) << rec.warningMessages;
  vtkImageData* out = reader->GetOutput();
  double outSpacing[3];
  out->GetSpacing(outSpacing);
  for (int a = 0; a < 3; ++a)
    EXPECT_NEAR(outSpacing[a], spacing[a], 1e-6);
  // Every filled voxel is a voxel of the label map, and there are as many.
  vtkNew<vtkMatrix4x4> toCT;
  vtkMatrix4x4::Invert(matrix, toCT);
  // The voxels of `label` in a reader's output, and how many of them are
  // voxels of the label map.
  auto compare = [&](vtkLKMedicalImageReader* read, int layer, int value) {
    vtkImageData* image = read->GetOutput();
    double h[3];
    int size[3];
    image->GetSpacing(h);
    image->GetDimensions(size);
    std::pair<vtkIdType, vtkIdType> filledAndRight{ 0, 0 };
    for (int k = 0; k < size[2]; ++k)
      for (int j = 0; j < size[1]; ++j)
        for (int i = 0; i < size[0]; ++i)
          if (image->GetScalarComponentAsDouble(i, j, k, layer) == value)
          {
            ++filledAndRight.first;
            const double p[4] = { i * h[0], j * h[1], k * h[2], 1.0 };
            double q[4], r[4];
            read->GetPatientMatrix()->MultiplyPoint(p, q);
            toCT->MultiplyPoint(q, r);
            int at[3];
            bool onGrid = true;
            for (int a = 0; a < 3; ++a)
            {
              at[a] = static_cast<int>(std::lround(r[a] / spacing[a]));
              onGrid = onGrid && std::abs(r[a] / spacing[a] - at[a]) < 1e-3 && at[a] >= 0 && at[a] < n[a];
            }
            filledAndRight.second += onGrid && ct->GetScalarComponentAsDouble(at[0], at[1], at[2], 0) > 0.0 ? 1 : 0;
          }
    return filledAndRight;
  };
  const auto [filled, right] = compare(reader, 0, 1);
  EXPECT_EQ(filled, inside);
  EXPECT_EQ(right, inside);

  // Its bone surface is the label map's.
  auto volumeOf = [](vtkAlgorithm* source, const char* name) {
    vtkNew<vtkLKBoneSurfaceFilter> bone;
    bone->SetInputConnection(source->GetOutputPort());
    if (name)
      bone->SetLabelName(name);
    else
      bone->SetLabel(1);
    vtkNew<vtkMassProperties> mass;
    mass->SetInputConnection(bone->GetOutputPort());
    mass->Update();
    return mass->GetVolume();
  };
  const double fromContours = volumeOf(reader, "Mandible"), fromLabels = volumeOf(nrrd, nullptr);
  EXPECT_GT(fromLabels, 10000.0); // mm^3: a mandible
  EXPECT_NEAR(fromContours, fromLabels, 0.005 * fromLabels);

  // Contoured on every other slice beside a body contoured on every slice
  // (as a planner contours an organ and lets the system fill in): the slices
  // between are interpolated from their neighbours' shapes.
  RoiSpec everyOther{ 1, "Mandible", {} }, body{ 2, "Body", {} };
  for (std::size_t c = 0; c < mandible.contours.size(); ++c)
    if (contourSlice[c] % 2 == 0)
      everyOther.contours.push_back(mandible.contours[c]);
  for (int k = 0; k < n[2]; ++k)
  {
    Polygon square;
    for (const auto& corner : { std::array<double, 2>{ -0.5, -0.5 }, { n[0] - 0.5, -0.5 }, { n[0] - 0.5, n[1] - 0.5 },
           { -0.5, n[1] - 0.5 } })
    {
      double x[4] = { corner[0] * spacing[0], corner[1] * spacing[1], k * spacing[2], 1.0 }, y[4];
      matrix->MultiplyPoint(x, y);
      square.push_back({ y[0], y[1], y[2] });
    }
    body.contours.push_back(square);
  }
  writeStructureSet(dir + "/rtstruct.dcm", { everyOther, body }, uid);
  vtkNew<vtkLKMedicalImageReader> sparse;
  lktest::ErrorRecorder sparseRec(sparse);
  sparse->SetFileName((dir + "/rtstruct.dcm").c_str());
  sparse->Update();
  ASSERT_EQ(sparseRec.errors, 0) << sparseRec.messages;
  EXPECT_NE(sparseRec.warningMessages.find("ROI 'Mandible' has no contour on "), std::string::npos);
  EXPECT_NE(sparseRec.warningMessages.find("they are filled by interpolating the contours on either side"),
    std::string::npos)
    << sparseRec.warningMessages;
  const auto [sparseFilled, sparseRight] = compare(sparse, 0, 1);
  const double dice = 2.0 * sparseRight / static_cast<double>(sparseFilled + inside);
  EXPECT_GT(dice, 0.95); // 0.962: 19,806 of the 19,959 voxels filled are the label map's 21,222
  EXPECT_GT(sparseFilled, inside * 9 / 10);
}

namespace
{
/// A closed box [x0, x1] x [y0, y1] x [z0, z1] (patient mm), triangulated.
vtkSmartPointer<vtkPolyData> box(double x0, double x1, double y0, double y1, double z0, double z1)
{
  vtkNew<vtkCubeSource> cube;
  cube->SetBounds(x0, x1, y0, y1, z0, z1);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(cube->GetOutputPort());
  triangles->Update();
  return triangles->GetOutput();
}
} // namespace

TEST(DicomStructureSet, SurfacesAreWrittenOnTheSlicesOfTheirCT)
{
  // Two boxes written as ROIs of a set that belongs to the CT they lie in:
  // its study and frame of reference, each contour on a CT slice naming its
  // image. Read back, they fill the CT's voxels they cover, exactly.
  const std::string dir = tempFolder("rtstruct_written");
  const std::string uid = writeSmallCT(dir);
  vtkNew<vtkLKStructureSetWriter> writer;
  lktest::ErrorRecorder rec(writer);
  writer->AddInputData(box(-10.5, -2.5, -5.5, 4.5, -5.0, 5.0));  // 8 x 10 pixels on the slices -4 to 4: 400
  writer->AddInputData(box(0.5, 10.5, 0.5, 10.5, -1.0, 3.0));    // 10 x 10 on 0 and 2: 200
  writer->SetROIName(0, "Mandible");
  writer->SetROIName(1, "Resection");
  writer->SetReferenceFileName(dir.c_str());
  writer->SetFileName((dir + "/plan.dcm").c_str());
  ASSERT_EQ(writer->Write(), 1) << rec.messages;
  EXPECT_EQ(rec.errors + rec.warnings, 0) << rec.messages << rec.warningMessages;
  EXPECT_EQ(writer->GetNumberOfContours(), 7);
  EXPECT_FALSE(vtksys::SystemTools::FileExists(dir + "/plan.dcm.part"));

  vtkNew<vtkDICOMMetaData> written, ct;
  for (auto [file, meta] : { std::make_pair(dir + "/plan.dcm", written.GetPointer()),
         std::make_pair(dir + "/ct_001.dcm", ct.GetPointer()) })
  {
    vtkNew<vtkDICOMParser> parser;
    parser->SetFileName(file.c_str());
    parser->SetMetaData(meta);
    parser->Update();
  }
  EXPECT_EQ(written->Get(DC::StudyInstanceUID).AsString(), ct->Get(DC::StudyInstanceUID).AsString());
  EXPECT_EQ(written->Get(DC::PatientID).AsString(), ct->Get(DC::PatientID).AsString());
  // A PACS stores an object by its UIDs (Type 1): a series and an instance
  // of its own, the instance named alike in the file's meta information.
  const std::string instance = written->Get(DC::SOPInstanceUID).AsString();
  const std::string setSeries = written->Get(DC::SeriesInstanceUID).AsString();
  EXPECT_FALSE(instance.empty());
  EXPECT_EQ(written->Get(DC::MediaStorageSOPInstanceUID).AsString(), instance);
  EXPECT_FALSE(setSeries.empty());
  EXPECT_NE(setSeries, uid);
  EXPECT_EQ(written->Get(DC::Modality).AsString(), "RTSTRUCT");
  // Type 2 attributes are there, if empty.
  for (vtkDICOMTag tag : { DC::PatientName, DC::PatientBirthDate, DC::PatientSex, DC::StudyDate, DC::StudyTime,
         DC::StudyID, DC::AccessionNumber, DC::ReferringPhysicianName, DC::OperatorsName, DC::SeriesNumber,
         DC::StructureSetDate, DC::StructureSetTime })
    EXPECT_TRUE(written->Get(tag).IsValid()) << tag;
  const vtkDICOMItem& frame = written->Get(DC::ReferencedFrameOfReferenceSequence).GetSequenceData()[0];
  EXPECT_EQ(frame.Get(DC::FrameOfReferenceUID).AsString(), ct->Get(DC::FrameOfReferenceUID).AsString());
  const vtkDICOMItem& series = frame.Get(DC::RTReferencedStudySequence).GetSequenceData()[0]
                                 .Get(DC::RTReferencedSeriesSequence).GetSequenceData()[0];
  EXPECT_EQ(series.Get(DC::SeriesInstanceUID).AsString(), uid);
  EXPECT_EQ(series.Get(DC::ContourImageSequence).GetNumberOfValues(), 12u); // every CT image
  const vtkDICOMItem& firstContour = written->Get(DC::ROIContourSequence).GetSequenceData()[0]
                                       .Get(DC::ContourSequence).GetSequenceData()[0];
  EXPECT_EQ(firstContour.Get(DC::ContourImageSequence).GetNumberOfValues(), 1u);

  vtkNew<vtkLKMedicalImageReader> reader;
  lktest::ErrorRecorder readRec(reader);
  reader->SetFileName((dir + "/plan.dcm").c_str());
  reader->Update();
  ASSERT_EQ(readRec.errors, 0) << readRec.messages;
  EXPECT_EQ(readRec.warnings, 0) << readRec.warningMessages; // the CT's grid, no gaps
  ASSERT_EQ(reader->GetNumberOfSegments(), 2);
  EXPECT_STREQ(reader->GetSegmentName(1), "Resection");
  EXPECT_EQ(count(reader->GetOutput(), 0, 1), 400);
  EXPECT_EQ(count(reader->GetOutput(), 0, 2), 200);
}

TEST(DicomStructureSet, TheMandibleSurfaceWrittenAndReadBackKeepsItsShape)
{
  // The TCIA mandible's bone surface, without a CT to refer to: contours on
  // axial planes 1 mm apart, read back on a grid of their own.
  vtkNew<vtkLKMedicalImageReader> nrrd;
  nrrd->SetFileName(lktest::sampleData("mandible-tcia/test_oncologist_0522c0017_Mandible.nrrd").c_str());
  vtkNew<vtkLKBoneSurfaceFilter> bone;
  bone->SetInputConnection(nrrd->GetOutputPort());
  vtkNew<vtkMassProperties> original;
  original->SetInputConnection(bone->GetOutputPort());
  original->Update();
  const std::string dir = tempFolder("rtstruct_mandible_written");
  vtkNew<vtkLKStructureSetWriter> writer;
  lktest::ErrorRecorder rec(writer);
  writer->SetInputConnection(bone->GetOutputPort());
  writer->SetROIName(0, "Mandible");
  writer->SetFileName((dir + "/mandible.dcm").c_str());
  ASSERT_EQ(writer->Write(), 1) << rec.messages;
  EXPECT_EQ(rec.warnings, 0) << rec.warningMessages;
  EXPECT_GT(writer->GetNumberOfContours(), 80);
  {
    // Without a CT: a new study, and the patient's Type 2 attributes empty.
    vtkNew<vtkDICOMMetaData> written;
    vtkNew<vtkDICOMParser> parser;
    parser->SetFileName((dir + "/mandible.dcm").c_str());
    parser->SetMetaData(written);
    parser->Update();
    for (vtkDICOMTag tag : { DC::SOPInstanceUID, DC::SeriesInstanceUID, DC::StudyInstanceUID })
      EXPECT_FALSE(written->Get(tag).AsString().empty()) << tag;
    for (vtkDICOMTag tag : { DC::PatientName, DC::PatientID, DC::StudyDate, DC::ReferringPhysicianName })
    {
      EXPECT_TRUE(written->Get(tag).IsValid()) << tag;
      EXPECT_EQ(written->Get(tag).AsString(), "") << tag;
    }
  }

  vtkNew<vtkLKMedicalImageReader> reader;
  reader->SetFileName((dir + "/mandible.dcm").c_str());
  lktest::ErrorRecorder readRec(reader); // "not in its folder": no CT
  vtkNew<vtkLKBoneSurfaceFilter> again;
  again->SetInputConnection(reader->GetOutputPort());
  again->SetLabelName("Mandible");
  vtkNew<vtkMassProperties> back;
  back->SetInputConnection(again->GetOutputPort());
  back->Update();
  ASSERT_EQ(readRec.errors, 0) << readRec.messages;
  EXPECT_NEAR(back->GetVolume(), original->GetVolume(), 0.03 * original->GetVolume());
  double b1[6], b2[6];
  bone->GetOutput()->GetBounds(b1);
  again->GetOutput()->GetBounds(b2);
  for (int a = 0; a < 6; ++a)
    EXPECT_NEAR(b1[a], b2[a], 1.5) << a;
}

TEST(DicomStructureSet, LongSectionsAreOneContourAndOpenOnesAreLeftOut)
{
  // A cylinder of 3,000 facets: each section one closed contour of 3,000
  // points (vtkStripper's default cut them into open pieces of 1,000).
  vtkNew<vtkCylinderSource> cylinder;
  cylinder->SetResolution(3000);
  cylinder->SetRadius(20.0);
  cylinder->SetHeight(10.5);
  cylinder->SetCenter(0.0, 0.0, 0.0);
  vtkNew<vtkTransform> upright; // the source's axis is y: turn it along z
  upright->RotateX(90.0);
  vtkNew<vtkTransformPolyDataFilter> turned;
  turned->SetTransform(upright);
  turned->SetInputConnection(cylinder->GetOutputPort());
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(turned->GetOutputPort());
  const std::string dir = tempFolder("rtstruct_long");
  vtkNew<vtkLKStructureSetWriter> writer;
  lktest::ErrorRecorder rec(writer);
  writer->SetInputConnection(triangles->GetOutputPort());
  writer->SetSliceSpacing(2.0);
  writer->SetFileName((dir + "/cylinder.dcm").c_str());
  ASSERT_EQ(writer->Write(), 1) << rec.messages;
  EXPECT_EQ(writer->GetNumberOfContours(), 5); // z = -4, -2, 0, 2, 4
  EXPECT_EQ(writer->GetNumberOfOpenContours(), 0);
  EXPECT_EQ(rec.warnings, 0) << rec.warningMessages;

  // A box without its top: its sections are open, left out with a warning.
  vtkSmartPointer<vtkPolyData> open = box(0, 5, 0, 5, -3, 3);
  vtkNew<vtkPolyData> cut;
  cut->SetPoints(open->GetPoints());
  vtkNew<vtkCellArray> faces;
  for (vtkIdType c = 0; c < open->GetNumberOfCells(); ++c)
  {
    double centre[3] = { 0, 0, 0 };
    vtkIdList* ids = open->GetCell(c)->GetPointIds();
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
      centre[0] += open->GetPoint(ids->GetId(k))[0] / ids->GetNumberOfIds();
    if (centre[0] < 4.99) // drop the face at x = 5: every section is open
      faces->InsertNextCell(ids);
  }
  cut->SetPolys(faces);
  vtkNew<vtkAppendPolyData> both; // an open part and a closed one in one surface
  both->AddInputData(cut);
  both->AddInputData(box(10, 15, 0, 5, -3, 3));
  vtkNew<vtkLKStructureSetWriter> openWriter;
  lktest::ErrorRecorder openRec(openWriter);
  openWriter->SetInputConnection(both->GetOutputPort());
  openWriter->SetSliceSpacing(2.0);
  openWriter->SetFileName((dir + "/open.dcm").c_str());
  ASSERT_EQ(openWriter->Write(), 1) << openRec.messages;
  EXPECT_GE(openWriter->GetNumberOfOpenContours(), 3); // at least one piece per plane
  EXPECT_EQ(openWriter->GetNumberOfContours(), 3); // the closed box's
  EXPECT_NE(openRec.warningMessages.find(" open piece(s) of contour left out: a surface is not closed where the planes "
                                        "cut it."),
    std::string::npos)
    << openRec.warningMessages;

  // Nothing but open sections: an error that says how to close it.
  vtkNew<vtkLKStructureSetWriter> onlyOpen;
  lktest::ErrorRecorder onlyOpenRec(onlyOpen);
  onlyOpen->AddInputData(cut);
  onlyOpen->SetROIName(0, "Skull");
  onlyOpen->SetSliceSpacing(2.0);
  onlyOpen->SetFileName((dir + "/only_open.dcm").c_str());
  EXPECT_EQ(onlyOpen->Write(), 0);
  EXPECT_NE(onlyOpenRec.messages.find("'Skull' (input 0) has only open sections on the contour planes ("),
    std::string::npos)
    << onlyOpenRec.messages;
  EXPECT_NE(onlyOpenRec.messages.find(" open pieces): the surface is not closed where they cut it (close it first"),
    std::string::npos)
    << onlyOpenRec.messages;
  EXPECT_FALSE(vtksys::SystemTools::FileExists(dir + "/only_open.dcm"));
}

TEST(DicomStructureSet, WritingBadInputIsAClearErrorAndKeepsAnEarlierFile)
{
  const std::string dir = tempFolder("rtstruct_write_errors");
  auto write = [&](vtkLKStructureSetWriter* writer, std::string& messages) {
    lktest::ErrorRecorder rec(writer);
    writer->Write();
    messages = rec.messages;
    return rec.errors;
  };
  std::string messages;
  {
    vtkNew<vtkLKStructureSetWriter> writer;
    writer->AddInputData(box(0, 5, 0, 5, 0, 5));
    EXPECT_EQ(write(writer, messages), 1);
    EXPECT_NE(messages.find("No FileName given."), std::string::npos) << messages;
  }
  {
    // tests/data/nan_sphere.vtp: a sphere with a point of NaN.
    vtkNew<vtkXMLPolyDataReader> sphere;
    sphere->SetFileName((std::string(LATTICEKIT_TEST_DATA) + "/nan_sphere.vtp").c_str());
    sphere->Update();
    vtkNew<vtkLKStructureSetWriter> writer;
    writer->SetInputConnection(sphere->GetOutputPort());
    writer->SetSliceSpacing(0.1);
    writer->SetFileName((dir + "/x.dcm").c_str());
    EXPECT_EQ(write(writer, messages), 1);
    EXPECT_NE(messages.find("Input 0 has a point whose coordinates are not numbers."), std::string::npos) << messages;
  }
  {
    vtkNew<vtkLKStructureSetWriter> writer;
    writer->AddInputData(vtkNew<vtkPolyData>());
    writer->SetFileName((dir + "/x.dcm").c_str());
    EXPECT_EQ(write(writer, messages), 1);
    EXPECT_NE(messages.find("Input 0 has no faces"), std::string::npos) << messages;
  }
  for (double spacing : { 0.0, std::numeric_limits<double>::quiet_NaN(), 1000.0 })
  {
    vtkNew<vtkLKStructureSetWriter> writer;
    writer->AddInputData(box(0, 5, 0, 5, 0, 5));
    writer->SetSliceSpacing(spacing);
    writer->SetFileName((dir + "/x.dcm").c_str());
    EXPECT_EQ(write(writer, messages), 1);
    EXPECT_NE(messages.find("SliceSpacing must be 0.01 to 100 mm"), std::string::npos) << messages;
  }
  {
    // A box that lies between two planes 10 mm apart.
    vtkNew<vtkLKStructureSetWriter> writer;
    writer->AddInputData(box(0, 5, 0, 5, 1, 4));
    writer->SetSliceSpacing(10.0);
    writer->SetROIName(0, "Chip");
    writer->SetFileName((dir + "/x.dcm").c_str());
    EXPECT_EQ(write(writer, messages), 1);
    EXPECT_NE(messages.find("'Chip' (input 0) crosses none of the contour planes"), std::string::npos) << messages;
  }
  {
    vtkNew<vtkLKStructureSetWriter> writer;
    writer->AddInputData(box(0, 5, 0, 5, 0, 5));
    writer->SetReferenceFileName((dir + "/no-such-ct").c_str());
    writer->SetFileName((dir + "/x.dcm").c_str());
    EXPECT_EQ(write(writer, messages), 1);
    EXPECT_NE(messages.find("Cannot use the reference CT"), std::string::npos) << messages;
  }
  EXPECT_FALSE(vtksys::SystemTools::FileExists(dir + "/x.dcm"));
  {
    // An earlier file survives a write that fails.
    std::ofstream(dir + "/kept.dcm") << "earlier";
    vtkNew<vtkLKStructureSetWriter> writer;
    writer->AddInputData(box(0, 5, 0, 5, 1, 4));
    writer->SetSliceSpacing(10.0);
    writer->SetFileName((dir + "/kept.dcm").c_str());
    EXPECT_EQ(write(writer, messages), 1);
    std::string kept;
    std::getline(std::ifstream(dir + "/kept.dcm"), kept);
    EXPECT_EQ(kept, "earlier");
  }
  {
    // A pipe is not replaced by a file (nor would /dev/null be).
    ASSERT_EQ(mkfifo((dir + "/pipe.dcm").c_str(), 0600), 0);
    vtkNew<vtkLKStructureSetWriter> writer;
    writer->AddInputData(box(0, 5, 0, 5, 0, 5));
    writer->SetFileName((dir + "/pipe.dcm").c_str());
    EXPECT_EQ(write(writer, messages), 1);
    EXPECT_NE(messages.find("Cannot write '" + dir + "/pipe.dcm': it is not a regular file."), std::string::npos)
      << messages;
    struct stat info;
    ASSERT_EQ(stat((dir + "/pipe.dcm").c_str(), &info), 0);
    EXPECT_TRUE(S_ISFIFO(info.st_mode));
  }
  {
    // A link: the file it points to is written, and the link stays.
    std::ofstream(dir + "/real.dcm") << "earlier";
    ASSERT_TRUE(vtksys::SystemTools::CreateSymlink("real.dcm", dir + "/link.dcm"));
    vtkNew<vtkLKStructureSetWriter> writer;
    writer->AddInputData(box(0, 5, 0, 5, 0, 5));
    writer->SetFileName((dir + "/link.dcm").c_str());
    EXPECT_EQ(write(writer, messages), 0) << messages;
    EXPECT_TRUE(vtksys::SystemTools::FileIsSymlink(dir + "/link.dcm"));
    EXPECT_TRUE(lkvtk::isDICOMStructureSet(dir + "/real.dcm"));
  }
  {
    // A folder of the file's name: the reason, and no part file left.
    vtksys::SystemTools::MakeDirectory(dir + "/folder.dcm");
    vtkNew<vtkLKStructureSetWriter> writer;
    writer->AddInputData(box(0, 5, 0, 5, 0, 5));
    writer->SetFileName((dir + "/folder.dcm").c_str());
    EXPECT_EQ(write(writer, messages), 1);
    EXPECT_NE(messages.find("Cannot write '" + dir + "/folder.dcm': Is a directory."), std::string::npos) << messages;
    EXPECT_FALSE(vtksys::SystemTools::FileExists(dir + "/folder.dcm.part"));
  }
  {
    // The file cannot take its place (a folder of the same name is in the
    // way): an error, and no part file left behind.
    vtkNew<vtkLKStructureSetWriter> writer;
    writer->AddInputData(box(0, 5, 0, 5, 0, 5));
    writer->SetFileName((dir + "/blocked").c_str());
    vtksys::SystemTools::MakeDirectory(dir + "/blocked/inside");
    EXPECT_EQ(write(writer, messages), 1);
    EXPECT_NE(messages.find("Cannot write '" + dir + "/blocked'"), std::string::npos) << messages;
    EXPECT_FALSE(vtksys::SystemTools::FileExists(dir + "/blocked.part"));
    EXPECT_TRUE(vtksys::SystemTools::FileIsDirectory(dir + "/blocked/inside"));
  }
}

TEST(DicomStructureSet, NamesInOtherCharacterSetsAreReadAndWrittenInUTF8)
{
  // Read: a German hospital's ROI "Kieferhöhle" in Latin-1, declared and
  // (as older systems wrote it) undeclared, and in UTF-8, undeclared and
  // declared. Each name comes back in UTF-8, so that a label typed on the
  // command line finds it.
  const std::string dir = tempFolder("rtstruct_character_sets");
  const std::string utf8 = "Kieferh\xC3\xB6hle", latin1 = "Kieferh\xF6hle";
  struct Case
  {
    const char* folder;
    const char* characterSet;
    std::string bytes;
  };
  for (const Case& c : { Case{ "latin1", "ISO_IR 100", latin1 }, Case{ "latin1_undeclared", nullptr, latin1 },
         Case{ "utf8_undeclared", nullptr, utf8 }, Case{ "utf8", "ISO_IR 192", utf8 } })
  {
    SCOPED_TRACE(c.folder);
    const std::string file = dir + "/" + c.folder + "/rs.dcm";
    vtksys::SystemTools::MakeDirectory(dir + "/" + c.folder);
    writeStructureSet(file,
      { { 2, c.bytes, { rectangle(0.5, 5.5, 0.5, 5.5, 0.0), rectangle(0.5, 5.5, 0.5, 5.5, 2.0) } } }, "1.2.3", 0, 0,
      nullptr, std::string(), c.characterSet);
    vtkNew<vtkLKMedicalImageReader> reader;
    reader->SetFileName(file.c_str());
    lktest::ErrorRecorder quiet(reader); // no CT beside it
    vtkNew<vtkLKBoneSurfaceFilter> bone;
    lktest::ErrorRecorder rec(bone);
    bone->SetInputConnection(reader->GetOutputPort());
    bone->SetLabelName(utf8.c_str());
    bone->Update();
    EXPECT_EQ(rec.errors, 0) << rec.messages;
    EXPECT_EQ(bone->GetEffectiveLabel(), 2);
    ASSERT_EQ(reader->GetNumberOfSegments(), 1);
    EXPECT_EQ(std::string(reader->GetSegmentName(0)), utf8);
  }

  // Written on a Latin-1 CT (its patient "Müller"): a name Latin-1 spells is
  // written in Latin-1, as the CT is; a Greek one ("Κάτω γνάθος") makes the
  // set UTF-8, and the patient's name goes with it. Both read back.
  vtkNew<vtkDICOMMetaData> german;
  german->Set(DC::SpecificCharacterSet, "ISO_IR 100");
  german->Set(DC::PatientName, "M\xFCller^Hans");
  vtksys::SystemTools::MakeDirectory(dir + "/ct");
  writeSmallCT(dir + "/ct", "%s/ct_%03d.dcm", nullptr, german);
  vtksys::SystemTools::MakeDirectory(dir + "/rt");
  const std::string greek = "\xCE\x9A\xCE\xAC\xCF\x84\xCF\x89 \xCE\xB3\xCE\xBD\xCE\xAC\xCE\xB8\xCE\xBF\xCF\x82";
  struct Written
  {
    std::string name, characterSet, nameBytes, patientBytes;
  };
  for (const Written& w : { Written{ utf8, "ISO_IR 100", latin1, "M\xFCller^Hans" },
         Written{ greek, "ISO_IR 192", greek, "M\xC3\xBCller^Hans" } })
  {
    SCOPED_TRACE(w.characterSet);
    const std::string file = dir + "/rt/" + (w.name == greek ? "greek.dcm" : "german.dcm");
    vtkNew<vtkLKStructureSetWriter> writer;
    lktest::ErrorRecorder rec(writer);
    writer->AddInputData(box(-10.5, -2.5, -5.5, 4.5, -5.0, 5.0));
    writer->SetROIName(0, w.name.c_str());
    writer->SetReferenceFileName((dir + "/ct").c_str());
    writer->SetFileName(file.c_str());
    ASSERT_EQ(writer->Write(), 1) << rec.messages;
    vtkNew<vtkDICOMMetaData> meta;
    vtkNew<vtkDICOMParser> parser;
    parser->SetFileName(file.c_str());
    parser->SetMetaData(meta);
    parser->Update();
    EXPECT_EQ(meta->Get(DC::SpecificCharacterSet).AsString(), w.characterSet);
    EXPECT_EQ(meta->Get(DC::StructureSetROISequence).GetSequenceData()[0].Get(DC::ROIName).AsString(), w.nameBytes);
    EXPECT_EQ(meta->Get(DC::PatientName).AsString(), w.patientBytes);
    vtkNew<vtkLKMedicalImageReader> reader;
    lktest::ErrorRecorder readRec(reader);
    reader->SetFileName(file.c_str());
    reader->Update();
    EXPECT_EQ(readRec.errors, 0) << readRec.messages;
    ASSERT_EQ(reader->GetNumberOfSegments(), 1);
    EXPECT_EQ(std::string(reader->GetSegmentName(0)), w.name);
  }

  // A Japanese CT (ISO 2022 with JIS X 0208, as Japanese hospitals' systems
  // write): a name in kanji ("下顎骨", mandible) is written in the CT's
  // character set, with its escape sequences, and reads back.
  {
    vtkNew<vtkDICOMMetaData> japanese;
    japanese->Set(DC::SpecificCharacterSet, "\\ISO 2022 IR 87");
    vtksys::SystemTools::MakeDirectory(dir + "/ct_jp");
    writeSmallCT(dir + "/ct_jp", "%s/ct_%03d.dcm", nullptr, japanese);
    const std::string kanji = "\xE4\xB8\x8B\xE9\xA1\x8E\xE9\xAA\xA8";
    vtkNew<vtkLKStructureSetWriter> writer;
    lktest::ErrorRecorder rec(writer);
    writer->AddInputData(box(-10.5, -2.5, -5.5, 4.5, -5.0, 5.0));
    writer->SetROIName(0, kanji.c_str());
    writer->SetReferenceFileName((dir + "/ct_jp").c_str());
    writer->SetFileName((dir + "/rt/japanese.dcm").c_str());
    ASSERT_EQ(writer->Write(), 1) << rec.messages;
    vtkNew<vtkDICOMMetaData> meta;
    vtkNew<vtkDICOMParser> parser;
    parser->SetFileName((dir + "/rt/japanese.dcm").c_str());
    parser->SetMetaData(meta);
    parser->Update();
    EXPECT_EQ(meta->Get(DC::SpecificCharacterSet).AsString(), "\\ISO 2022 IR 87");
    const std::string bytes = meta->Get(DC::StructureSetROISequence).GetSequenceData()[0].Get(DC::ROIName).AsString();
    EXPECT_EQ(bytes.substr(0, 3), "\x1B$B"); // JIS X 0208 switched in
    vtkNew<vtkLKMedicalImageReader> reader;
    lktest::ErrorRecorder readRec(reader);
    reader->SetFileName((dir + "/rt/japanese.dcm").c_str());
    reader->Update();
    EXPECT_EQ(readRec.errors, 0) << readRec.messages;
    ASSERT_EQ(reader->GetNumberOfSegments(), 1);
    EXPECT_EQ(std::string(reader->GetSegmentName(0)), kanji);
  }

  // Names DICOM cannot hold are refused, with the reason; a name of 64
  // two-byte characters is not one of them.
  std::string umlauts;
  for (int i = 0; i < 64; ++i)
    umlauts += "\xC3\xB6";
  struct Bad
  {
    std::string name, label, message;
  };
  for (const Bad& b : { Bad{ "upper\\lower", "latticekit", "holds a backslash, which DICOM reads as a separator" },
         Bad{ std::string(65, 'x'), "latticekit", "is longer than 64 characters" },
         Bad{ "Kieferh\xF6hle", "latticekit", "is not UTF-8 text" }, Bad{ "a\nb", "latticekit", "holds a control character" },
         Bad{ umlauts, "latticekit plan 2026", "The StructureSetLabel 'latticekit plan 2026' is longer than 16" },
         Bad{ umlauts, "", "The StructureSetLabel '' is empty" }, Bad{ umlauts, "latticekit", "" } })
  {
    vtkNew<vtkLKStructureSetWriter> writer;
    lktest::ErrorRecorder rec(writer);
    writer->AddInputData(box(-10.5, -2.5, -5.5, 4.5, -5.0, 5.0));
    writer->SetROIName(0, b.name.c_str());
    writer->SetStructureSetLabel(b.label.c_str());
    writer->SetFileName((dir + "/rt/bad.dcm").c_str());
    writer->Write();
    EXPECT_EQ(rec.errors, b.message.empty() ? 0 : 1) << b.message;
    EXPECT_NE(rec.messages.find(b.message), std::string::npos) << rec.messages;
    EXPECT_EQ(vtksys::SystemTools::FileExists(dir + "/rt/bad.dcm"), b.message.empty());
  }
}

TEST(DicomStructureSet, MarkersAreWrittenAsPointROIsAfterTheSurfaces)
{
  // A measured distance's ends as landmarks beside a surface: one POINT
  // contour each, interpreted as MARKER, numbered after the surfaces; a
  // name beyond ASCII makes the set UTF-8 as a surface's name does. The
  // set still reads back as its surface (the markers passed over).
  vtkNew<vtkCubeSource> cube;
  cube->SetBounds(0, 20, 0, 20, 0, 20);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(cube->GetOutputPort());
  const std::string dir = tempFolder("rtstruct_markers");
  vtkNew<vtkLKStructureSetWriter> writer;
  lktest::ErrorRecorder rec(writer);
  writer->SetInputConnection(triangles->GetOutputPort());
  writer->SetROIName(0, "Block");
  writer->AddMarker("measurement 1, 5.00 mm: from", 1.0, 2.0, 3.0);
  writer->AddMarker("Messung 1, 5.00 mm: bis Kinnspitze \xC3\xA4", 4.0, 6.0, 3.0);
  EXPECT_EQ(writer->GetNumberOfMarkers(), 2);
  writer->SetFileName((dir + "/markers.dcm").c_str());
  ASSERT_EQ(writer->Write(), 1) << rec.messages;
  vtkNew<vtkDICOMMetaData> written;
  vtkNew<vtkDICOMParser> parser;
  parser->SetFileName((dir + "/markers.dcm").c_str());
  parser->SetMetaData(written);
  parser->Update();
  EXPECT_EQ(written->Get(DC::SpecificCharacterSet).AsString(), "ISO_IR 192");
  const vtkDICOMValue& listed = written->Get(DC::StructureSetROISequence);
  const vtkDICOMValue& contoured = written->Get(DC::ROIContourSequence);
  const vtkDICOMValue& observed = written->Get(DC::RTROIObservationsSequence);
  ASSERT_EQ(listed.GetNumberOfValues(), 3u);
  ASSERT_EQ(contoured.GetNumberOfValues(), 3u);
  ASSERT_EQ(observed.GetNumberOfValues(), 3u);
  EXPECT_EQ(listed.GetSequenceData()[0].Get(DC::ROIName).AsString(), "Block");
  EXPECT_EQ(observed.GetSequenceData()[0].Get(DC::RTROIInterpretedType).AsString(), "ORGAN");
  for (unsigned int k = 1; k < 3; ++k)
  {
    EXPECT_EQ(listed.GetSequenceData()[k].Get(DC::ROINumber).AsInt(), static_cast<int>(k) + 1);
    EXPECT_EQ(observed.GetSequenceData()[k].Get(DC::RTROIInterpretedType).AsString(), "MARKER");
    const vtkDICOMValue& contours = contoured.GetSequenceData()[k].Get(DC::ContourSequence);
    ASSERT_EQ(contours.GetNumberOfValues(), 1u);
    const vtkDICOMItem& point = contours.GetSequenceData()[0];
    EXPECT_EQ(point.Get(DC::ContourGeometricType).AsString(), "POINT");
    EXPECT_EQ(point.Get(DC::NumberOfContourPoints).AsInt(), 1);
    EXPECT_EQ(point.Get(DC::ContourData).AsString(), k == 1 ? "1\\2\\3" : "4\\6\\3");
  }
  EXPECT_EQ(listed.GetSequenceData()[2].Get(DC::ROIName).AsUTF8String(), "Messung 1, 5.00 mm: bis Kinnspitze \xC3\xA4");

  vtkNew<vtkLKMedicalImageReader> reader;
  reader->SetFileName((dir + "/markers.dcm").c_str());
  lktest::ErrorRecorder readRec(reader);
  vtkNew<vtkLKBoneSurfaceFilter> again;
  again->SetInputConnection(reader->GetOutputPort());
  again->SetLabelName("Block");
  vtkNew<vtkMassProperties> back;
  back->SetInputConnection(again->GetOutputPort());
  back->Update();
  ASSERT_EQ(readRec.errors, 0) << readRec.messages;
  EXPECT_NEAR(back->GetVolume(), 8000.0, 0.1 * 8000.0);

  // Markers that DICOM cannot hold are refused with the reason.
  for (const auto& [name, x, why] : std::vector<std::tuple<std::string, double, std::string>>{
         { "", 0.0, "is empty" }, { "a\\b", 0.0, "backslash" }, { "fine", std::nan(""), "not a number" } })
  {
    vtkNew<vtkLKStructureSetWriter> bad;
    lktest::ErrorRecorder badRec(bad);
    bad->SetInputConnection(triangles->GetOutputPort());
    bad->AddMarker(name.c_str(), x, 0.0, 0.0);
    bad->SetFileName((dir + "/bad.dcm").c_str());
    EXPECT_EQ(bad->Write(), 0) << name;
    EXPECT_NE(badRec.messages.find(why), std::string::npos) << badRec.messages;
    EXPECT_FALSE(vtksys::SystemTools::FileExists(dir + "/bad.dcm"));
  }
}
