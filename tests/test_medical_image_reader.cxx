#include "DicomTestFiles.h"
#include "TestSupport.h"
#include "vtkLKMedicalImageReader.h"

#include <vtkDICOMCompiler.h>
#include <vtkDICOMImageReader.h>
#include <vtkDICOMItem.h>
#include <vtkDICOMMetaData.h>
#include <vtkDICOMReader.h>
#include <vtkDICOMSequence.h>
#include <vtkDICOMValue.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkImageInterpolator.h>
#include <vtkIntArray.h>
#include <vtkMatrix4x4.h>
#include <vtkMetaImageWriter.h>
#include <vtkNIFTIImageReader.h>
#include <vtkNIFTIImageWriter.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkStringArray.h>
#include <vtksys/SystemTools.hxx>

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <cstdio>
#include <fstream>
#include <tuple>

namespace
{
const std::string geFolder = lktest::sampleData("dicom-ct-ge-tilt");

std::string tempFolder(const std::string& name)
{
  const std::string dir = std::string(LATTICEKIT_TEST_TMP) + "/" + name;
  vtksys::SystemTools::RemoveADirectory(dir);
  vtksys::SystemTools::MakeDirectory(dir);
  return dir;
}

void copyGESeries(const std::string& dir)
{
  for (int i = 1; i <= 28; ++i)
  {
    char name[16];
    std::snprintf(name, sizeof(name), "/%02d.dcm", i);
    vtksys::SystemTools::CopyAFile(geFolder + name, dir + name);
  }
}

/// A synthetic CT series written by vtkDICOM into `dir` with the file name
/// pattern `pattern` (e.g. "%s/slice_%03d.dcm"): `slices` slices of size x
/// size voxels of 1 mm, `gap` mm apart, every voxel `value`.
void writeSyntheticSeries(const std::string& dir, const char* pattern, int size, int slices, double gap, short value,
  const char* description = nullptr)
{
  vtkNew<vtkImageData> img;
  img->SetDimensions(size, size, slices);
  img->SetSpacing(1.0, 1.0, gap);
  img->AllocateScalars(VTK_SHORT, 1);
  std::fill_n(static_cast<short*>(img->GetScalarPointer()), size * size * slices, value);
  lktest::writeCT(dir, img, nullptr, pattern, description);
}

/// The output's "SPACE" field data (3D Slicer's tag), or "".
std::string spaceTag(vtkImageData* image)
{
  auto* tag = vtkStringArray::SafeDownCast(image->GetFieldData()->GetAbstractArray("SPACE"));
  return tag && tag->GetNumberOfValues() == 1 ? tag->GetValue(0) : std::string();
}

/// Median of |a - b| over the pairs.
double medianAbs(std::vector<double> d)
{
  std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
  return d[d.size() / 2];
}
} // namespace

TEST(MedicalImageReader, GantryTiltedSeriesMatchesEverySlicePosition)
{
  vtkNew<vtkLKMedicalImageReader> reader;
  reader->SetFileName(geFolder.c_str());
  reader->Update();
  ASSERT_STREQ(reader->GetFileFormat(), "DICOM");
  EXPECT_EQ(reader->GetNumberOfInputSlices(), 28);
  EXPECT_NEAR(reader->GetGantryTilt(), 18.5, 0.05);
  EXPECT_TRUE(reader->GetOrientationKnown());
  EXPECT_EQ(spaceTag(reader->GetOutput()), "LPS");
  EXPECT_LT(reader->GetMinimumSliceGap(), 1.2);
  EXPECT_GT(reader->GetMaximumSliceGap(), 6.5);
  vtkImageData* volume = reader->GetOutput();
  vtkMatrix4x4* matrix = reader->GetPatientMatrix();
  vtkNew<vtkMatrix4x4> toData;
  vtkMatrix4x4::Invert(matrix, toData);

  // The raw slices and their own ImagePositionPatient, through vtkDICOMReader.
  vtkNew<vtkDICOMReader> raw;
  vtkNew<vtkStringArray> files;
  for (int i = 1; i <= 28; ++i)
  {
    char name[16];
    std::snprintf(name, sizeof(name), "/%02d.dcm", i);
    files->InsertNextValue(geFolder + name);
  }
  raw->SetFileNames(files);
  raw->SetMemoryRowOrderToFileNative();
  raw->Update();
  vtkImageData* rawImage = raw->GetOutput();
  int dims[3];
  rawImage->GetDimensions(dims);
  ASSERT_EQ(dims[2], 28);

  vtkNew<vtkImageInterpolator> interpolator;
  interpolator->SetInterpolationModeToLinear();
  interpolator->SetOutValue(-5000.0);
  interpolator->Initialize(volume);

  // Naive geometry for comparison: slices stacked along the normal at one
  // average spacing, tilt ignored (what a reader that trusts a single
  // spacing does).
  double zFirst = 0, zLast = 0;
  std::vector<std::array<double, 3>> ipp(28);
  std::vector<double> iop(6);
  for (int k = 0; k < 28; ++k)
  {
    const int f = raw->GetFileIndexArray()->GetComponent(k, 0);
    raw->GetMetaData()->Get(f, DC::ImagePositionPatient).GetValues(ipp[static_cast<std::size_t>(k)].data(), 3);
  }
  raw->GetMetaData()->Get(0, DC::ImageOrientationPatient).GetValues(iop.data(), 6);
  double ps[2];
  raw->GetMetaData()->Get(0, DC::PixelSpacing).GetValues(ps, 2);
  const double r[3] = { iop[0], iop[1], iop[2] }, c[3] = { iop[3], iop[4], iop[5] };
  const double n[3] = { r[1] * c[2] - r[2] * c[1], r[2] * c[0] - r[0] * c[2], r[0] * c[1] - r[1] * c[0] };
  std::vector<double> zs(28);
  for (int k = 0; k < 28; ++k)
  {
    zs[static_cast<std::size_t>(k)] = n[0] * ipp[k][0] + n[1] * ipp[k][1] + n[2] * ipp[k][2];
  }
  zFirst = *std::min_element(zs.begin(), zs.end());
  zLast = *std::max_element(zs.begin(), zs.end());
  const double naiveSpacing = (zLast - zFirst) / 27.0;

  std::vector<double> errCorrect, errNaive;
  for (int k = 0; k < 28; ++k)
  {
    const double order = static_cast<double>(std::count_if(
      zs.begin(), zs.end(), [&](double z) { return z < zs[static_cast<std::size_t>(k)]; }));
    for (int j = 96; j < dims[1] - 96; j += 16)
    {
      for (int i = 96; i < dims[0] - 96; i += 16)
      {
        const double value = rawImage->GetScalarComponentAsDouble(i, j, k, 0);
        double p[4] = { 0, 0, 0, 1 };
        for (int a = 0; a < 3; ++a)
        {
          p[a] = ipp[k][a] + i * ps[1] * r[a] + j * ps[0] * c[a];
        }
        double d[4];
        toData->MultiplyPoint(p, d);
        double sampled;
        interpolator->Interpolate(d, &sampled);
        ASSERT_GT(sampled, -5000.0) << "slice " << k << " pixel " << i << "," << j
                                    << " falls outside the volume";
        errCorrect.push_back(std::abs(sampled - value));
        const double naive[3] = { i * ps[1], j * ps[0], order * naiveSpacing };
        double naiveSample;
        interpolator->Interpolate(naive, &naiveSample);
        errNaive.push_back(std::abs(naiveSample - value));
      }
    }
  }
  const double correct = medianAbs(errCorrect), naive = medianAbs(errNaive);
  std::printf("median |difference| at the slices' own positions: %.2f HU (naive geometry: %.2f HU)\n",
    correct, naive);
  EXPECT_LT(correct, 3.0); // bilinear and between-slice interpolation only
  EXPECT_GT(naive, 10.0 * std::max(correct, 0.5));

  // VTK's plain reader reports one spacing, which the gaps contradict.
  vtkNew<vtkDICOMImageReader> plain;
  plain->SetDirectoryName(geFolder.c_str());
  plain->Update();
  const double plainSpacing = plain->GetOutput()->GetSpacing()[2];
  EXPECT_TRUE(std::abs(plainSpacing - reader->GetMinimumSliceGap()) > 0.5 ||
    std::abs(plainSpacing - reader->GetMaximumSliceGap()) > 0.5);
  // The matrix is a rotation (the volume was rectified, not sheared).
  EXPECT_NEAR(matrix->Determinant(), 1.0, 1e-9);
  // And it travels with the image.
  vtkDataArray* stored = volume->GetFieldData()->GetArray("PatientMatrix");
  ASSERT_NE(stored, nullptr);
  EXPECT_EQ(stored->GetTuple1(3), matrix->GetElement(0, 3));
}

TEST(MedicalImageReader, RescaledSeriesReadsInHounsfieldUnitsInPositionOrder)
{
  // Three slices of a Philips skull phantom: 12-bit unsigned pixels with
  // RescaleIntercept -1024, as nearly every CT stores them. Their names (I90,
  // I100, I110) sort the wrong way as text, and the folder holds a LICENSE
  // file that is not DICOM.
  const std::string folder = lktest::sampleData("dicom-ct-philips-phantom");
  vtkNew<vtkLKMedicalImageReader> reader;
  lktest::ErrorRecorder rec(reader);
  reader->SetFileName(folder.c_str());
  reader->Update();
  ASSERT_EQ(rec.errors, 0) << rec.messages;
  ASSERT_STREQ(reader->GetFileFormat(), "DICOM");
  EXPECT_EQ(reader->GetNumberOfInputSlices(), 3);
  EXPECT_NEAR(reader->GetGantryTilt(), 0.0, 1e-9);
  EXPECT_NEAR(reader->GetMinimumSliceGap(), 5.0, 1e-6);
  EXPECT_NEAR(reader->GetMaximumSliceGap(), 5.0, 1e-6);
  vtkImageData* volume = reader->GetOutput();
  int dims[3];
  volume->GetDimensions(dims);
  ASSERT_EQ(dims[0], 512);
  ASSERT_EQ(dims[1], 512);
  ASSERT_EQ(dims[2], 3);
  EXPECT_NEAR(volume->GetSpacing()[2], 5.0, 1e-6);

  // Slice k of the volume is the file at the k-th position along the slice
  // normal, and holds its stored values times RescaleSlope plus
  // RescaleIntercept, every voxel.
  const char* byPosition[3] = { "/I90", "/I100", "/I110" }; // z = 736.21, 741.21, 746.21
  double lowest[3] = { 0, 0, 0 };
  vtkIdType bone = 0;
  for (int k = 0; k < 3; ++k)
  {
    vtkNew<vtkDICOMReader> raw;
    raw->SetFileName((folder + byPosition[k]).c_str());
    raw->SetMemoryRowOrderToFileNative();
    raw->AutoRescaleOff();
    raw->Update();
    vtkDICOMMetaData* meta = raw->GetMetaData();
    const double slope = meta->Get(DC::RescaleSlope).AsDouble();
    const double intercept = meta->Get(DC::RescaleIntercept).AsDouble();
    ASSERT_EQ(slope, 1.0);
    ASSERT_EQ(intercept, -1024.0);
    if (k == 0)
    {
      meta->Get(DC::ImagePositionPatient).GetValues(lowest, 3);
    }
    vtkImageData* stored = raw->GetOutput();
    ASSERT_EQ(stored->GetDimensions()[0], 512);
    vtkIdType mismatches = 0;
    for (int j = 0; j < 512; ++j)
    {
      for (int i = 0; i < 512; ++i)
      {
        const double hu = volume->GetScalarComponentAsDouble(i, j, k, 0);
        mismatches += hu != stored->GetScalarComponentAsDouble(i, j, 0, 0) * slope + intercept;
        bone += hu > 300.0;
      }
    }
    EXPECT_EQ(mismatches, 0) << "slice " << k << " (" << byPosition[k] << ")";
  }
  EXPECT_EQ(volume->GetScalarRange()[0], -1024.0); // air outside the field of view
  EXPECT_GT(bone, 30000); // the phantom's skull at 300 HU in all three slices
  // The patient matrix puts voxel 0 at the lowest slice's ImagePositionPatient.
  for (int a = 0; a < 3; ++a)
  {
    EXPECT_NEAR(reader->GetPatientMatrix()->GetElement(a, 3), lowest[a], 1e-6);
  }
}

namespace
{
/// An Enhanced CT Image (one file, every slice a frame, the geometry in
/// functional groups: pixel spacing, orientation and rescale shared, each
/// frame's ImagePositionPatient its own), as recent scanners export a CT. It
/// is made of the bundled phantom's three slices, the frames in the order
/// `files` gives, the stored values and attributes as they are in the slices.
/// Without `orientation` or `positions` the file lacks the shared plane
/// orientation or the frames' positions (a damaged or non-conforming export).
void writeEnhancedCT(const std::string& path, const std::string& folder, const std::vector<std::string>& files,
  bool orientation = true, bool positions = true)
{
  std::vector<unsigned short> pixels;
  vtkNew<vtkDICOMMetaData> meta;
  vtkDICOMSequence perFrame;
  for (std::size_t k = 0; k < files.size(); ++k)
  {
    vtkNew<vtkDICOMReader> raw;
    raw->SetFileName((folder + files[k]).c_str());
    raw->SetMemoryRowOrderToFileNative();
    raw->AutoRescaleOff();
    raw->Update();
    vtkDICOMMetaData* m = raw->GetMetaData();
    vtkImageData* img = raw->GetOutput();
    ASSERT_EQ(img->GetScalarType(), VTK_UNSIGNED_SHORT);
    const auto* p = static_cast<const unsigned short*>(img->GetScalarPointer());
    pixels.insert(pixels.end(), p, p + img->GetNumberOfPoints());
    if (k == 0)
    {
      for (const vtkDICOMTag tag : { DC::PatientName, DC::PatientID, DC::StudyInstanceUID, DC::StudyID,
             DC::StudyDate, DC::StudyTime, DC::Rows, DC::Columns, DC::BitsAllocated, DC::BitsStored, DC::HighBit,
             DC::PixelRepresentation, DC::SamplesPerPixel, DC::PhotometricInterpretation })
      {
        if (m->Get(tag).IsValid())
          meta->Set(tag, m->Get(tag));
      }
      vtkDICOMItem measures, plane, rescale, shared;
      measures.Set(DC::PixelSpacing, m->Get(DC::PixelSpacing));
      measures.Set(DC::SliceThickness, m->Get(DC::SliceThickness));
      plane.Set(DC::ImageOrientationPatient, m->Get(DC::ImageOrientationPatient));
      rescale.Set(DC::RescaleIntercept, m->Get(DC::RescaleIntercept));
      rescale.Set(DC::RescaleSlope, m->Get(DC::RescaleSlope));
      rescale.Set(DC::RescaleType, "HU");
      shared.Set(DC::PixelMeasuresSequence, vtkDICOMSequence(measures));
      if (orientation)
        shared.Set(DC::PlaneOrientationSequence, vtkDICOMSequence(plane));
      shared.Set(DC::PixelValueTransformationSequence, vtkDICOMSequence(rescale));
      meta->Set(DC::SharedFunctionalGroupsSequence, vtkDICOMSequence(shared));
    }
    vtkDICOMItem position, content, frame;
    position.Set(DC::ImagePositionPatient, m->Get(DC::ImagePositionPatient));
    content.Set(DC::InStackPositionNumber, static_cast<double>(k + 1));
    if (positions)
      frame.Set(DC::PlanePositionSequence, vtkDICOMSequence(position));
    frame.Set(DC::FrameContentSequence, vtkDICOMSequence(content));
    perFrame.AddItem(frame);
  }
  meta->Set(DC::SOPClassUID, "1.2.840.10008.5.1.4.1.1.2.1"); // Enhanced CT Image Storage
  meta->Set(DC::Modality, "CT");
  meta->Set(DC::ImageType, "ORIGINAL\\PRIMARY\\AXIAL\\NONE");
  meta->Set(DC::SeriesNumber, 1.0);
  meta->Set(DC::InstanceNumber, 1.0);
  meta->Set(DC::NumberOfFrames, static_cast<double>(files.size()));
  meta->Set(DC::PerFrameFunctionalGroupsSequence, perFrame);
  meta->Set(DC::PixelData, vtkDICOMValue(vtkDICOMVR::OW)); // its element is written with the frames
  vtkNew<vtkDICOMCompiler> compiler;
  compiler->SetFileName(path.c_str());
  compiler->SetMetaData(meta);
  compiler->WriteHeader();
  const std::size_t frame = pixels.size() / files.size();
  for (std::size_t k = 0; k < files.size(); ++k)
    compiler->WriteFrame(reinterpret_cast<const unsigned char*>(pixels.data() + k * frame),
      static_cast<vtkIdType>(frame * sizeof(unsigned short)));
  compiler->Close();
  ASSERT_EQ(compiler->GetErrorCode(), 0u);
}
} // namespace

// The same three slices as one Enhanced CT file, their frames stored out of
// position order: the same volume, voxel for voxel, in the same place.
TEST(MedicalImageReader, EnhancedMultiFrameCTReadsAsItsSlicesDo)
{
  const std::string folder = lktest::sampleData("dicom-ct-philips-phantom");
  const std::string dir = tempFolder("enhanced_ct");
  writeEnhancedCT(dir + "/enhanced.dcm", folder, { "/I110", "/I90", "/I100" });
  // The same file twice in one folder: one series (the same UIDs) whose
  // frames lie two at each position, which vtkDICOMReader stacks as
  // components. Said as such, not as colour images.
  const std::string twice = tempFolder("enhanced_ct_twice");
  vtksys::SystemTools::CopyAFile(dir + "/enhanced.dcm", twice + "/a.dcm");
  vtksys::SystemTools::CopyAFile(dir + "/enhanced.dcm", twice + "/b.dcm");
  {
    vtkNew<vtkLKMedicalImageReader> reader;
    lktest::ErrorRecorder rec(reader);
    reader->SetFileName(twice.c_str());
    reader->Update();
    EXPECT_EQ(rec.errors, 1);
    EXPECT_NE(rec.messages.find("cannot be stacked into one volume: several lie at one position"), std::string::npos)
      << rec.messages;
  }
  vtkNew<vtkLKMedicalImageReader> series;
  series->SetFileName(folder.c_str());
  series->Update();
  for (const std::string& input : { dir, dir + "/enhanced.dcm" })
  {
    SCOPED_TRACE(input);
    vtkNew<vtkLKMedicalImageReader> reader;
    lktest::ErrorRecorder rec(reader);
    reader->SetFileName(input.c_str());
    reader->Update();
    ASSERT_EQ(rec.errors, 0) << rec.messages;
    EXPECT_EQ(rec.warnings, 0) << rec.warningMessages;
    ASSERT_STREQ(reader->GetFileFormat(), "DICOM");
    EXPECT_EQ(reader->GetNumberOfInputSlices(), 3);
    EXPECT_NEAR(reader->GetMinimumSliceGap(), 5.0, 1e-6);
    vtkImageData* a = reader->GetOutput();
    vtkImageData* b = series->GetOutput();
    ASSERT_EQ(std::vector<int>(a->GetDimensions(), a->GetDimensions() + 3),
      std::vector<int>(b->GetDimensions(), b->GetDimensions() + 3));
    for (int i = 0; i < 3; ++i)
    {
      EXPECT_NEAR(a->GetSpacing()[i], b->GetSpacing()[i], 1e-9);
      EXPECT_NEAR(a->GetOrigin()[i], b->GetOrigin()[i], 1e-9);
    }
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c)
        EXPECT_NEAR(reader->GetPatientMatrix()->GetElement(r, c), series->GetPatientMatrix()->GetElement(r, c), 1e-9);
    vtkIdType differ = 0;
    for (vtkIdType v = 0; v < a->GetNumberOfPoints(); ++v)
      differ += a->GetPointData()->GetScalars()->GetComponent(v, 0) != b->GetPointData()->GetScalars()->GetComponent(v, 0);
    EXPECT_EQ(differ, 0);
    EXPECT_EQ(a->GetScalarRange()[0], -1024.0); // rescaled, as the slices are
  }

  // Without the orientation or the frames' positions: a clear error. (The
  // first read above crashed the reader, which looked for the orientation
  // outside the functional groups and read a value that was not there.)
  for (const bool orientation : { false, true })
  {
    // Each in a folder of its own: the series shares its UIDs with the one above.
    const std::string path =
      tempFolder(orientation ? "enhanced_ct_no_positions" : "enhanced_ct_no_orientation") + "/enhanced.dcm";
    writeEnhancedCT(path, folder, { "/I90", "/I100", "/I110" }, orientation, !orientation);
    vtkNew<vtkLKMedicalImageReader> reader;
    lktest::ErrorRecorder rec(reader);
    reader->SetFileName(path.c_str());
    reader->Update();
    EXPECT_EQ(rec.errors, 1);
    EXPECT_NE(rec.messages.find(orientation ? "a DICOM slice has no ImagePositionPatient"
                                            : "the DICOM series has no ImageOrientationPatient or PixelSpacing"),
      std::string::npos)
      << rec.messages;
    EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
  }
}

// PACS exports are often compressed. The phantom's slices, RLE Lossless
// (vtkDICOM encodes it; the decoding is the reader's): the same volume.
TEST(MedicalImageReader, CompressedSeriesReadsAsTheUncompressedOne)
{
  const std::string folder = lktest::sampleData("dicom-ct-philips-phantom");
  const std::string dir = tempFolder("rle_ct");
  for (const char* name : { "/I90", "/I100", "/I110" })
  {
    vtkNew<vtkDICOMReader> raw;
    raw->SetFileName((folder + name).c_str());
    raw->SetMemoryRowOrderToFileNative();
    raw->AutoRescaleOff();
    raw->Update();
    vtkDICOMMetaData* m = raw->GetMetaData();
    vtkNew<vtkDICOMMetaData> meta;
    for (auto it = m->Begin(); it != m->End(); ++it)
      if (it->GetTag().GetGroup() > 2)
        meta->Set(it->GetTag(), it->GetValue());
    vtkNew<vtkDICOMCompiler> compiler;
    compiler->SetFileName((dir + name).c_str());
    compiler->SetMetaData(meta);
    compiler->SetTransferSyntaxUID("1.2.840.10008.1.2.5"); // RLE Lossless
    compiler->SetSOPInstanceUID(m->Get(DC::SOPInstanceUID).AsString().c_str());
    compiler->SetSeriesInstanceUID(m->Get(DC::SeriesInstanceUID).AsString().c_str());
    compiler->WriteHeader();
    vtkImageData* img = raw->GetOutput();
    compiler->WriteFrame(static_cast<const unsigned char*>(img->GetScalarPointer()),
      img->GetNumberOfPoints() * img->GetScalarSize());
    compiler->Close();
    ASSERT_EQ(compiler->GetErrorCode(), 0u);
    ASSERT_LT(vtksys::SystemTools::FileLength(dir + name), vtksys::SystemTools::FileLength(folder + name));
  }
  vtkNew<vtkLKMedicalImageReader> plain, compressed;
  plain->SetFileName(folder.c_str());
  plain->Update();
  lktest::ErrorRecorder rec(compressed);
  compressed->SetFileName(dir.c_str());
  compressed->Update();
  ASSERT_EQ(rec.errors, 0) << rec.messages;
  vtkImageData* a = compressed->GetOutput();
  vtkImageData* b = plain->GetOutput();
  ASSERT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
  ASSERT_EQ(a->GetNumberOfPoints(), 512 * 512 * 3);
  vtkIdType differ = 0;
  for (vtkIdType v = 0; v < a->GetNumberOfPoints(); ++v)
    differ += a->GetPointData()->GetScalars()->GetComponent(v, 0) != b->GetPointData()->GetScalars()->GetComponent(v, 0);
  EXPECT_EQ(differ, 0);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(a->GetOrigin()[i], b->GetOrigin()[i], 1e-9);
}

// JPEG Lossless, JPEG-LS and JPEG 2000 Lossless, one slice each (gdcmconv
// wrote them, scripts/make_jpeg_dicom_test_data.sh; GDCM decodes them
// inside vtkDICOMReader): the phantom, voxel for voxel.
TEST(MedicalImageReader, JPEGCompressedSeriesReadsAsTheUncompressedOne)
{
  vtkNew<vtkLKMedicalImageReader> plain, jpeg;
  plain->SetFileName(lktest::sampleData("dicom-ct-philips-phantom").c_str());
  plain->Update();
  lktest::ErrorRecorder rec(jpeg);
  jpeg->SetFileName(LATTICEKIT_TEST_DATA "/dicom-phantom-jpeg");
  jpeg->Update();
  ASSERT_EQ(rec.errors, 0) << rec.messages;
  vtkImageData* a = jpeg->GetOutput();
  vtkImageData* b = plain->GetOutput();
  ASSERT_EQ(a->GetNumberOfPoints(), 512 * 512 * 3);
  ASSERT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
  vtkIdType differ = 0;
  for (vtkIdType v = 0; v < a->GetNumberOfPoints(); ++v)
    differ += a->GetPointData()->GetScalars()->GetComponent(v, 0) != b->GetPointData()->GetScalars()->GetComponent(v, 0);
  EXPECT_EQ(differ, 0);
  double range[2];
  a->GetScalarRange(range);
  EXPECT_EQ(range[0], -1024.0);
  EXPECT_GT(range[1], 700.0);
}

// A compressed slice that GDCM cannot decode: vtkDICOMReader left it as the
// buffer was (blank) and read on without a word, so the bone surface had a
// slice missing. Now the read fails and names the file and its compression.
TEST(MedicalImageReader, DamagedJPEGSliceIsAnErrorNotABlankSlice)
{
  const std::string source = LATTICEKIT_TEST_DATA "/dicom-phantom-jpeg";
  for (const char* name : { "/I90", "/I100" }) // JPEG Lossless, JPEG-LS
  {
    const std::string dir = tempFolder("damaged_jpeg");
    for (const char* f : { "/I90", "/I100", "/I110" })
      ASSERT_TRUE(vtksys::SystemTools::CopyAFile(source + f, dir + f));
    {
      // Bytes flipped in the middle of the compressed stream.
      std::fstream file(dir + name, std::ios::in | std::ios::out | std::ios::binary);
      ASSERT_TRUE(file.good());
      file.seekg(0, std::ios::end);
      const std::streamoff size = file.tellg();
      for (std::streamoff at = size / 2; at < size / 2 + 2000; at += 7)
      {
        char c = 0;
        file.seekg(at);
        file.get(c);
        file.seekp(at);
        file.put(static_cast<char>(c ^ 0x5a));
      }
    }
    vtkNew<vtkLKMedicalImageReader> reader;
    lktest::ErrorRecorder rec(reader);
    reader->SetFileName(dir.c_str());
    reader->Update();
    EXPECT_GE(rec.errors, 1) << name;
    EXPECT_NE(rec.messages.find(std::string(name) + "': its pixel data, compressed as JPEG"), std::string::npos)
      << rec.messages;
    EXPECT_NE(rec.messages.find("could not be decoded (the compressed data is damaged)"), std::string::npos)
      << rec.messages;
    EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
  }
}

TEST(MedicalImageReader, SliceSpacingIsHonoured)
{
  vtkNew<vtkLKMedicalImageReader> reader;
  reader->SetFileName(geFolder.c_str());
  reader->SetSliceSpacing(2.0);
  reader->Update();
  EXPECT_DOUBLE_EQ(reader->GetOutput()->GetSpacing()[2], 2.0);

  // A spacing beyond the series' extent gave two slices, the second 1e9 mm
  // away, and a bone surface of 5e11 mm^2: refused now.
  lktest::ErrorRecorder rec(reader);
  reader->SetSliceSpacing(1e9);
  reader->Update();
  EXPECT_EQ(rec.errors, 1);
  EXPECT_NE(rec.messages.find("larger than the series' extent"), std::string::npos) << rec.messages;
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);

  // A spacing of 1e-9 mm: 1e11 slices overflowed int into a volume of
  // -2147483647 slices, without an error. NaN was taken as automatic.
  reader->SetSliceSpacing(1e-9);
  reader->Update();
  EXPECT_EQ(rec.errors, 2);
  EXPECT_NE(rec.messages.find("the resampled volume would be too large"), std::string::npos) << rec.messages;
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
  reader->SetSliceSpacing(std::nan(""));
  reader->Update();
  EXPECT_EQ(rec.errors, 3);
  EXPECT_NE(rec.messages.find("SliceSpacing must be a number of mm (0: automatic), not NaN"), std::string::npos)
    << rec.messages;
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
}

// A 4D NRRD whose first axis is a list of values per voxel (3D Slicer's
// layers of overlapping segments). VTK 9.1's vtkNrrdReader read it as a 2D
// image ("space" after "dimension: 4" cut the sizes to three) and, gzipped,
// filled only part of the volume; a 4D file whose list axis is not first
// would be read scrambled, and is refused.
TEST(MedicalImageReader, NrrdWithALayerAxisReadsEveryLayer)
{
  const std::string file = LATTICEKIT_TEST_DATA "/overlapping_segments.seg.nrrd";
  std::ifstream in(file, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t headerEnd = bytes.find("\n\n") + 2;
  const std::string dir = tempFolder("layers");

  vtkNew<vtkLKMedicalImageReader> reader;
  lktest::ErrorRecorder rec(reader);
  reader->SetFileName(file.c_str());
  reader->Update();
  ASSERT_EQ(rec.errors, 0) << rec.messages;
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  EXPECT_EQ(dims[0], 40);
  EXPECT_EQ(dims[1], 30);
  EXPECT_EQ(dims[2], 30);
  ASSERT_EQ(image->GetNumberOfScalarComponents(), 2);
  EXPECT_DOUBLE_EQ(image->GetSpacing()[2], 2.0);
  // Voxel counts of the balls (scripts/make_label_test_data.py): r 8 and 7
  // in layer 0 (as in two_segments.seg.nrrd), r 6 in layer 1.
  std::array<std::array<int, 3>, 2> counts{};
  for (vtkIdType v = 0; v < image->GetNumberOfPoints(); ++v)
    for (int c = 0; c < 2; ++c)
      ++counts[c][static_cast<int>(image->GetPointData()->GetScalars()->GetComponent(v, c)) % 3];
  EXPECT_EQ(counts[0][1], 1031);
  EXPECT_EQ(counts[0][2], 695);
  EXPECT_EQ(counts[1][1], 425);
  EXPECT_EQ(counts[1][2], 0);

  // Cut short inside the gzip stream: an error, not a volume half zeros.
  std::ofstream(dir + "/cut.seg.nrrd", std::ios::binary) << bytes.substr(0, headerEnd + (bytes.size() - headerEnd) / 2);
  rec.errors = 0;
  rec.messages.clear();
  reader->SetFileName((dir + "/cut.seg.nrrd").c_str());
  reader->Update();
  EXPECT_GE(rec.errors, 1);
  EXPECT_NE(rec.messages.find("of the 72000 bytes its header asks for: the file is truncated or damaged"),
    std::string::npos)
    << rec.messages;

  // Time (or anything else) after the three space axes.
  std::ofstream(dir + "/time_last.nrrd", std::ios::binary)
    << "NRRD0004\ntype: unsigned char\ndimension: 4\nsizes: 4 4 4 2\nkinds: domain domain domain list\n"
       "encoding: raw\n\n"
    << std::string(128, '\1');
  rec.errors = 0;
  rec.messages.clear();
  reader->SetFileName((dir + "/time_last.nrrd").c_str());
  reader->Update();
  EXPECT_EQ(rec.errors, 1);
  EXPECT_NE(rec.messages.find("it has 4 axes (kinds: domain domain domain list) and only a 3D volume, with a list of "
                              "values per voxel first where there are 4, is read."),
    std::string::npos)
    << rec.messages;
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
  // Without kinds, a first axis of more than 9 is no list (VTK's own guess);
  // five axes are never read whole.
  std::ofstream(dir + "/no_kinds.nrrd", std::ios::binary)
    << "NRRD0004\ntype: unsigned char\ndimension: 4\nsizes: 12 4 4 2\nencoding: raw\n\n" << std::string(384, '\1');
  std::ofstream(dir + "/five.nrrd", std::ios::binary)
    << "NRRD0004\ntype: unsigned char\ndimension: 5\nsizes: 2 4 4 4 2\nkinds: list domain domain domain list\n"
       "encoding: raw\n\n"
    << std::string(256, '\1');
  for (const auto& [file, what] : { std::make_pair("no_kinds.nrrd", "it has 4 axes (sizes: 12 4 4 2)"),
         std::make_pair("five.nrrd", "it has 5 axes (kinds: list domain domain domain list)") })
  {
    rec.errors = 0;
    rec.messages.clear();
    reader->SetFileName((dir + "/" + file).c_str());
    reader->Update();
    EXPECT_EQ(rec.errors, 1) << file;
    EXPECT_NE(rec.messages.find(what), std::string::npos) << rec.messages;
    EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0) << file;
  }
}

TEST(MedicalImageReader, NrrdGeometryComesFromTheHeader)
{
  vtkNew<vtkLKMedicalImageReader> reader;
  reader->SetFileName(lktest::sampleData("mandible-tcia/test_oncologist_0522c0017_Mandible.nrrd").c_str());
  reader->Update();
  EXPECT_STREQ(reader->GetFileFormat(), "NRRD");
  int dims[3];
  reader->GetOutput()->GetDimensions(dims);
  EXPECT_EQ(dims[0], 512);
  EXPECT_EQ(dims[2], 156);
  EXPECT_NEAR(reader->GetOutput()->GetSpacing()[0], 0.98, 1e-9);
  EXPECT_NEAR(reader->GetOutput()->GetSpacing()[2], 2.5, 1e-9);
  vtkMatrix4x4* m = reader->GetPatientMatrix();
  EXPECT_NEAR(m->GetElement(0, 3), -250.38999938964844, 1e-9);
  EXPECT_NEAR(m->GetElement(1, 3), 155.61000061035156, 1e-9);
  EXPECT_NEAR(m->GetElement(2, 3), -1178.0, 1e-9);
  EXPECT_NEAR(m->Determinant(), 1.0, 1e-12);
  // "space: left-posterior-superior": the axes are the patient's, and the
  // output says so in 3D Slicer's tag.
  EXPECT_TRUE(reader->GetOrientationKnown());
  EXPECT_EQ(spaceTag(reader->GetOutput()), "LPS");
}

TEST(MedicalImageReader, MetaImageRoundTrip)
{
  vtkNew<vtkLKMedicalImageReader> nrrd;
  nrrd->SetFileName(lktest::sampleData("mandible-tcia/test_oncologist_TCGA-CV-7236_Mandible.nrrd").c_str());
  nrrd->Update();
  vtkNew<vtkImageData> shifted;
  shifted->ShallowCopy(nrrd->GetOutput());
  shifted->SetOrigin(10.0, -20.0, 30.0);
  const std::string path = tempFolder("mha") + "/mandible.mha";
  vtkNew<vtkMetaImageWriter> writer;
  writer->SetInputData(shifted);
  writer->SetFileName(path.c_str());
  writer->SetCompression(true);
  writer->Write();
  vtkNew<vtkLKMedicalImageReader> mha;
  mha->SetFileName(path.c_str());
  mha->Update();
  EXPECT_STREQ(mha->GetFileFormat(), "MetaImage");
  EXPECT_EQ(mha->GetOutput()->GetNumberOfPoints(), nrrd->GetOutput()->GetNumberOfPoints());
  EXPECT_NEAR(mha->GetPatientMatrix()->GetElement(0, 3), 10.0, 1e-9);
  EXPECT_NEAR(mha->GetPatientMatrix()->GetElement(1, 3), -20.0, 1e-9);
  EXPECT_NEAR(mha->GetPatientMatrix()->GetElement(2, 3), 30.0, 1e-9);
  EXPECT_NEAR(mha->GetOutput()->GetSpacing()[2], nrrd->GetOutput()->GetSpacing()[2], 1e-6);
}

TEST(MedicalImageReader, NiftiWithoutOrientationKeepsDataCoordinatesAndWarns)
{
  vtkNew<vtkLKMedicalImageReader> reader;
  lktest::ErrorRecorder rec(reader);
  reader->SetFileName(lktest::sampleData("cthead/cthead_hu_approx.nii.gz").c_str());
  reader->Update();
  EXPECT_STREQ(reader->GetFileFormat(), "NIfTI");
  int dims[3];
  reader->GetOutput()->GetDimensions(dims);
  EXPECT_EQ(dims[0], 256);
  EXPECT_EQ(dims[2], 113);
  EXPECT_DOUBLE_EQ(reader->GetOutput()->GetSpacing()[2], 2.0);
  EXPECT_EQ(rec.warnings, 1);
  EXPECT_NE(rec.warningMessages.find("orientation is unknown"), std::string::npos);
  EXPECT_FALSE(reader->GetOrientationKnown());
  EXPECT_EQ(spaceTag(reader->GetOutput()), ""); // no claim of a patient system
  vtkNew<vtkMatrix4x4> identity;
  for (int i = 0; i < 16; ++i)
  {
    EXPECT_EQ(reader->GetPatientMatrix()->GetElement(i / 4, i % 4), identity->GetElement(i / 4, i % 4));
  }
}

namespace
{
/// A 10 x 12 x 14 int16 NIfTI-1 file, written byte by byte (VTK's writer
/// cannot make a left-handed qform), with one voxel at (2, 3, 4) set to 1000,
/// spacing 1, 1.5, 2, a qform turned 0.3 rad about z with offset (10, -20, 30)
/// (RAS) and the given qfac, and, when sform is given, that sform as well.
void writeNifti(const std::string& path, float qfac, short qformCode, short sformCode,
  const std::array<float, 12>& sform, float slope = 1.0f, float intercept = 0.0f)
{
  char h[352] = {};
  auto put = [&h](int offset, const void* value, std::size_t bytes) { std::memcpy(h + offset, value, bytes); };
  const int size = 348;
  put(0, &size, 4);
  const short dim[8] = { 3, 10, 12, 14, 1, 1, 1, 1 };
  put(40, dim, sizeof(dim));
  const short datatype = 4, bitpix = 16;
  put(70, &datatype, 2);
  put(72, &bitpix, 2);
  const float pixdim[8] = { qfac, 1.0f, 1.5f, 2.0f, 1, 1, 1, 1 };
  put(76, pixdim, sizeof(pixdim));
  const float voxOffset = 352.0f;
  put(108, &voxOffset, 4);
  put(112, &slope, 4);
  put(116, &intercept, 4);
  put(252, &qformCode, 2);
  put(254, &sformCode, 2);
  const float quatern[6] = { 0.0f, 0.0f, static_cast<float>(std::sin(0.15)), 10.0f, -20.0f, 30.0f };
  put(256, quatern, sizeof(quatern));
  put(280, sform.data(), sizeof(float) * 12);
  std::memcpy(h + 344, "n+1", 4);
  std::vector<short> voxels(10 * 12 * 14, 0);
  voxels[2 + 10 * (3 + 12 * 4)] = 1000;
  std::ofstream out(path, std::ios::binary);
  out.write(h, sizeof(h));
  out.write(reinterpret_cast<const char*>(voxels.data()), static_cast<std::streamsize>(voxels.size() * sizeof(short)));
}

/// Where the reader puts the voxel of value 1000: the patient (LPS) point.
std::array<double, 3> markedVoxelInPatientSpace(vtkLKMedicalImageReader* reader)
{
  vtkImageData* image = reader->GetOutput();
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < image->GetNumberOfPoints(); ++i)
  {
    if (scalars->GetTuple1(i) == 1000.0)
    {
      double p[4] = { 0, 0, 0, 1 };
      image->GetPoint(i, p);
      double q[4];
      reader->GetPatientMatrix()->MultiplyPoint(p, q);
      return { q[0], q[1], q[2] };
    }
  }
  ADD_FAILURE() << "no marked voxel";
  return { 0, 0, 0 };
}
} // namespace

// NIfTI's qform: RAS = R (i dx, j dy, qfac k dz) + offset. With qfac = -1 the
// slices run the other way (a left-handed grid, as many converters write
// axial CTs); VTK's reader flips them, and the patient matrix must put every
// voxel where the header says. Patient space is LPS, so x and y change sign.
TEST(MedicalImageReader, NiftiQformAndSformPlaceEveryVoxelInPatientSpace)
{
  const std::string dir = tempFolder("nifti_forms");
  const double a = 0.3;
  const double ras[2] = { 10.0 + std::cos(a) * 2.0 - std::sin(a) * 4.5, -20.0 + std::sin(a) * 2.0 + std::cos(a) * 4.5 };
  const std::array<float, 12> noSform = {};
  for (float qfac : { 1.0f, -1.0f })
  {
    const std::string path = dir + (qfac > 0 ? "/right.nii" : "/left.nii");
    writeNifti(path, qfac, 1, 0, noSform);
    vtkNew<vtkLKMedicalImageReader> reader;
    lktest::ErrorRecorder rec(reader);
    reader->SetFileName(path.c_str());
    reader->Update();
    ASSERT_EQ(rec.errors, 0) << rec.messages;
    EXPECT_EQ(rec.warnings, 0) << rec.warningMessages;
    EXPECT_TRUE(reader->GetOrientationKnown());
    EXPECT_EQ(spaceTag(reader->GetOutput()), "LPS");
    const auto p = markedVoxelInPatientSpace(reader);
    EXPECT_NEAR(p[0], -ras[0], 1e-4) << "qfac " << qfac;
    EXPECT_NEAR(p[1], -ras[1], 1e-4) << "qfac " << qfac;
    EXPECT_NEAR(p[2], 30.0 + qfac * 8.0, 1e-4) << "qfac " << qfac;
  }
  // An sform alone (qform_code 0): an oblique, left-handed affine, rows of
  // [i j k 1] -> RAS, with a shear the qform could not hold.
  const std::array<float, 12> sform = { -0.9f, 0.2f, 0.1f, 5.0f, 0.3f, 1.4f, 0.0f, -7.0f, 0.0f, 0.25f, 2.0f, 40.0f };
  const std::string path = dir + "/sform.nii";
  writeNifti(path, 1.0f, 0, 2, sform);
  vtkNew<vtkLKMedicalImageReader> reader;
  lktest::ErrorRecorder rec(reader);
  reader->SetFileName(path.c_str());
  reader->Update();
  ASSERT_EQ(rec.errors, 0) << rec.messages;
  const auto p = markedVoxelInPatientSpace(reader);
  const double ijk[3] = { 2, 3, 4 };
  double expected[3];
  for (int row = 0; row < 3; ++row)
  {
    expected[row] = sform[4 * row + 3];
    for (int c = 0; c < 3; ++c)
    {
      expected[row] += sform[4 * row + c] * ijk[c];
    }
  }
  EXPECT_NEAR(p[0], -expected[0], 1e-4);
  EXPECT_NEAR(p[1], -expected[1], 1e-4);
  EXPECT_NEAR(p[2], expected[2], 1e-4);
}

// dcm2niix keeps a CT's stored values and writes its RescaleIntercept to
// scl_inter (often -1024). The reader ignored scl_slope and scl_inter, and a
// 300 HU threshold then fell at -724 HU, in soft tissue, without a word.
TEST(MedicalImageReader, NiftiSclSlopeAndInterCalibrateTheValues)
{
  const std::string dir = tempFolder("nifti_scl");
  vtkNew<vtkLKMedicalImageReader> reference;
  reference->SetFileName(lktest::sampleData("cthead/cthead_hu_approx.nii.gz").c_str());
  reference->Update();
  vtkImageData* hu = reference->GetOutput();
  ASSERT_EQ(hu->GetScalarType(), VTK_SHORT);
  ASSERT_EQ(hu->GetScalarRange()[0], -1024.0);
  // Stored as HU + 1024 with scl_inter -1024, and as 2 (HU + 1024) in an
  // unsigned short with scl_slope 0.5.
  struct Case
  {
    const char* name;
    int type;
    double slope, intercept;
    int readType;
  };
  for (const Case& c : { Case{ "inter.nii.gz", VTK_SHORT, 1.0, -1024.0, VTK_SHORT },
         Case{ "slope.nii.gz", VTK_UNSIGNED_SHORT, 0.5, -1024.0, VTK_FLOAT } })
  {
    SCOPED_TRACE(c.name);
    vtkNew<vtkImageData> stored;
    stored->CopyStructure(hu);
    stored->AllocateScalars(c.type, 1);
    for (vtkIdType i = 0; i < hu->GetNumberOfPoints(); ++i)
      stored->GetPointData()->GetScalars()->SetTuple1(
        i, (hu->GetPointData()->GetScalars()->GetTuple1(i) - c.intercept) / c.slope);
    vtkNew<vtkNIFTIImageWriter> writer;
    writer->SetInputData(stored);
    writer->SetRescaleSlope(c.slope);
    writer->SetRescaleIntercept(c.intercept);
    writer->SetFileName((dir + "/" + c.name).c_str());
    writer->Write();
    vtkNew<vtkLKMedicalImageReader> reader;
    lktest::ErrorRecorder rec(reader);
    reader->SetFileName((dir + "/" + c.name).c_str());
    reader->Update();
    ASSERT_EQ(rec.errors, 0) << rec.messages;
    vtkImageData* read = reader->GetOutput();
    EXPECT_EQ(read->GetScalarType(), c.readType);
    ASSERT_EQ(read->GetNumberOfPoints(), hu->GetNumberOfPoints());
    vtkIdType differ = 0;
    for (vtkIdType i = 0; i < hu->GetNumberOfPoints(); ++i)
      differ += read->GetPointData()->GetScalars()->GetTuple1(i) != hu->GetPointData()->GetScalars()->GetTuple1(i);
    EXPECT_EQ(differ, 0);
  }
  // scl_slope 0 means no scaling (NIfTI-1); a NaN one is said and ignored.
  const std::array<float, 12> noSform = {};
  for (const float slope : { 0.0f, std::nanf("") })
  {
    const std::string path = dir + (slope == 0.0f ? "/zero.nii" : "/nan.nii");
    writeNifti(path, 1.0f, 1, 0, noSform, slope, -1024.0f);
    vtkNew<vtkLKMedicalImageReader> reader;
    lktest::ErrorRecorder rec(reader);
    reader->SetFileName(path.c_str());
    reader->Update();
    ASSERT_EQ(rec.errors, 0) << rec.messages;
    EXPECT_EQ(reader->GetOutput()->GetScalarRange()[1], 1000.0);
    EXPECT_EQ(rec.warnings, slope == 0.0f ? 0 : 1) << rec.warningMessages;
    if (slope != 0.0f)
      EXPECT_NE(rec.warningMessages.find("scl_slope or scl_inter that is not a number"), std::string::npos);
  }
}

// A registered image often keeps the scanner's qform and the target space's
// sform. The qform is used; when the two place the volume apart, a warning
// says by how much (nothing is said when they agree).
TEST(MedicalImageReader, NiftiQformAndSformThatDisagreeAreWarnedOf)
{
  const std::string dir = tempFolder("nifti_two_forms");
  const std::array<float, 12> noSform = {};
  writeNifti(dir + "/q.nii", 1.0f, 1, 0, noSform);
  vtkNew<vtkNIFTIImageReader> plain;
  plain->SetFileName((dir + "/q.nii").c_str());
  plain->Update();
  // The qform's own map as an sform (rows of [i j k 1] -> RAS), once as it
  // is and once moved 5 mm along x.
  vtkMatrix4x4* q = plain->GetQFormMatrix();
  const double* sp = plain->GetOutput()->GetSpacing();
  const double* o = plain->GetOutput()->GetOrigin();
  std::array<float, 12> same{};
  for (int row = 0; row < 3; ++row)
  {
    for (int c = 0; c < 3; ++c)
      same[4 * row + c] = static_cast<float>(q->GetElement(row, c) * sp[c]);
    same[4 * row + 3] = static_cast<float>(q->GetElement(row, 3) + q->GetElement(row, 0) * o[0] +
      q->GetElement(row, 1) * o[1] + q->GetElement(row, 2) * o[2]);
  }
  std::array<float, 12> moved = same;
  moved[3] += 5.0f;
  for (const bool apart : { false, true })
  {
    const std::string path = dir + (apart ? "/apart.nii" : "/agree.nii");
    writeNifti(path, 1.0f, 1, 1, apart ? moved : same);
    vtkNew<vtkLKMedicalImageReader> reader;
    lktest::ErrorRecorder rec(reader);
    reader->SetFileName(path.c_str());
    reader->Update();
    ASSERT_EQ(rec.errors, 0) << rec.messages;
    EXPECT_EQ(rec.warnings, apart ? 1 : 0) << rec.warningMessages;
    if (apart)
      EXPECT_NE(rec.warningMessages.find("has a qform and an sform that place the volume up to 5 mm apart "
                                         "(qform_code 1, sform_code 1): the qform is used"),
        std::string::npos)
        << rec.warningMessages;
  }
}

TEST(MedicalImageReader, TwoSeriesReadTheLargestAndWarnOrTheChosenOne)
{
  const std::string dir = tempFolder("two-series");
  copyGESeries(dir);
  // A second, synthetic CT series of 5 slices written by vtkDICOM.
  writeSyntheticSeries(dir, "%s/synthetic_%03d.dcm", 64, 5, 3.0, 100, "synthetic second series");

  vtkNew<vtkLKMedicalImageReader> reader;
  lktest::ErrorRecorder rec(reader);
  reader->SetFileName(dir.c_str());
  reader->Update();
  EXPECT_EQ(rec.errors, 0) << rec.messages;
  EXPECT_EQ(reader->GetNumberOfSeries(), 2);
  EXPECT_EQ(reader->GetNumberOfInputSlices(), 28);
  // The folder's two series, and the GE series' own variable spacing.
  EXPECT_EQ(rec.warnings, 2) << rec.warningMessages;
  EXPECT_NE(rec.warningMessages.find("2 series"), std::string::npos);
  EXPECT_NE(rec.warningMessages.find("The slices are not evenly spaced"), std::string::npos);
  EXPECT_EQ(rec.warningMessages.find(" in '"), std::string::npos) << rec.warningMessages; // one folder

  reader->SetSeriesIndex(1);
  reader->Update();
  EXPECT_EQ(reader->GetNumberOfInputSlices(), 5);
  EXPECT_EQ(reader->GetOutput()->GetDimensions()[0], 64);

  reader->SetSeriesIndex(2);
  reader->Update();
  EXPECT_GE(rec.errors, 1);
  EXPECT_NE(rec.messages.find("out of range"), std::string::npos);

  // A file of the small series selects that series.
  reader->SetSeriesIndex(-1);
  reader->SetFileName((dir + "/synthetic_002.dcm").c_str());
  rec.errors = 0;
  reader->Update();
  EXPECT_EQ(rec.errors, 0) << rec.messages;
  EXPECT_EQ(reader->GetNumberOfInputSlices(), 5);
}

// A hospital CD copied to disk keeps its images some folders down, a series
// per folder. Given the CD's top folder, the reader finds them, reads the
// largest and says where each series lies (the scout's, the bone kernel's).
TEST(MedicalImageReader, ACDsFoldersAreSearchedAndEachSeriesNamesItsFolder)
{
  const std::string cd = tempFolder("cd-copy");
  const std::string head = cd + "/DICOM/ST000000/SE000000", small = cd + "/DICOM/ST000000/SE000001";
  vtksys::SystemTools::MakeDirectory(head);
  vtksys::SystemTools::MakeDirectory(small);
  copyGESeries(head);
  writeSyntheticSeries(small, "%s/IM%06d", 64, 5, 3.0, 100, "scout");
  vtkNew<vtkLKMedicalImageReader> reader;
  lktest::ErrorRecorder rec(reader);
  reader->SetFileName(cd.c_str());
  reader->Update();
  ASSERT_EQ(rec.errors, 0) << rec.messages;
  EXPECT_EQ(reader->GetNumberOfSeries(), 2);
  EXPECT_EQ(reader->GetNumberOfInputSlices(), 28);
  EXPECT_NE(rec.warningMessages.find("28 images, CT"), std::string::npos) << rec.warningMessages;
  EXPECT_NE(rec.warningMessages.find("in 'DICOM/ST000000/SE000000'"), std::string::npos) << rec.warningMessages;
  EXPECT_NE(rec.warningMessages.find("'scout'"), std::string::npos) << rec.warningMessages;
  EXPECT_NE(rec.warningMessages.find("in 'DICOM/ST000000/SE000001'"), std::string::npos) << rec.warningMessages;
  reader->SetSeriesIndex(1);
  reader->Update();
  EXPECT_EQ(reader->GetNumberOfInputSlices(), 5);

  // Series in one folder are not given a folder each (the test above).
  // Deeper than the search goes: not found, and the message says how deep
  // it looked.
  std::string deep = tempFolder("cd-too-deep");
  const std::string top = deep;
  for (int level = 0; level < 8; ++level)
    deep += "/d";
  vtksys::SystemTools::MakeDirectory(deep);
  writeSyntheticSeries(deep, "%s/IM%06d", 16, 3, 2.0, 100);
  vtkNew<vtkLKMedicalImageReader> far;
  lktest::ErrorRecorder farRec(far);
  far->SetFileName(top.c_str());
  far->Update();
  EXPECT_EQ(farRec.errors, 1);
  EXPECT_NE(farRec.messages.find("or in its sub-folders (7 levels down)"), std::string::npos) << farRec.messages;
  far->SetFileName((top + "/d").c_str()); // seven levels above the images: found
  far->Update();
  EXPECT_EQ(farRec.errors, 1) << farRec.messages;
  EXPECT_EQ(far->GetNumberOfInputSlices(), 3);
}

// A CD with its DICOMDIR (tests/data/dicomdir/DICOMDIR, made by gdcmgendir
// for the phantom's three slices as DICOM/ST0/SE0/IM0 to IM2): the DICOMDIR
// itself, as viewers open a CD, reads as its folder does. A DICOMDIR that
// lists a file no longer there (a CD copied in part) is set aside, with a
// warning, and the folder's files are read.
TEST(MedicalImageReader, ACDsDICOMDIRReadsAsItsFolderAndAStaleOneIsSetAside)
{
  const std::string cd = tempFolder("cd-dicomdir");
  const std::string series = cd + "/DICOM/ST0/SE0";
  ASSERT_TRUE(vtksys::SystemTools::MakeDirectory(series));
  const char* slices[3] = { "I90", "I100", "I110" };
  for (int k = 0; k < 3; ++k)
    ASSERT_TRUE(vtksys::SystemTools::CopyAFile(
      lktest::sampleData(std::string("dicom-ct-philips-phantom/") + slices[k]), series + "/IM" + std::to_string(k)));
  ASSERT_TRUE(
    vtksys::SystemTools::CopyAFile(std::string(LATTICEKIT_TEST_DATA) + "/dicomdir/DICOMDIR", cd + "/DICOMDIR"));
  for (const std::string& input : { cd + "/DICOMDIR", cd })
  {
    vtkNew<vtkLKMedicalImageReader> reader;
    lktest::ErrorRecorder rec(reader);
    reader->SetFileName(input.c_str());
    reader->Update();
    ASSERT_EQ(rec.errors, 0) << input << ": " << rec.messages;
    EXPECT_EQ(rec.warnings, 0) << rec.warningMessages;
    EXPECT_STREQ(reader->GetFileFormat(), "DICOM");
    EXPECT_EQ(reader->GetNumberOfInputSlices(), 3);
    EXPECT_EQ(reader->GetOutput()->GetDimensions()[0], 512);
  }

  // IM1 renamed: the DICOMDIR lists a file that is not there.
  ASSERT_EQ(std::rename((series + "/IM1").c_str(), (series + "/im1.dcm").c_str()), 0);
  vtkNew<vtkLKMedicalImageReader> stale;
  lktest::ErrorRecorder staleRec(stale);
  stale->SetFileName((cd + "/DICOMDIR").c_str());
  stale->Update();
  ASSERT_EQ(staleRec.errors, 0) << staleRec.messages;
  EXPECT_EQ(stale->GetNumberOfInputSlices(), 3);
  EXPECT_NE(staleRec.warningMessages.find("its DICOMDIR lists 3 files, 1 of which is not there (a CD copied "
                                          "in part, or its files moved): the folder's files were read instead"),
    std::string::npos)
    << staleRec.warningMessages;
}

TEST(MedicalImageReader, ASeriesWithAMissingSliceIsWarned)
{
  // Eight slices 3 mm apart written by vtkDICOM; then the fifth is lost.
  const std::string dir = tempFolder("missing-slice");
  writeSyntheticSeries(dir, "%s/slice_%03d.dcm", 32, 8, 3.0, 400);

  vtkNew<vtkLKMedicalImageReader> reader;
  lktest::ErrorRecorder rec(reader);
  reader->SetFileName(dir.c_str());
  reader->Update();
  EXPECT_EQ(rec.errors, 0) << rec.messages;
  EXPECT_EQ(rec.warnings, 0) << "the complete series: " << rec.warningMessages;

  std::remove((dir + "/slice_004.dcm").c_str());
  reader->Modified();
  reader->Update();
  EXPECT_EQ(rec.errors, 0) << rec.messages;
  EXPECT_EQ(reader->GetNumberOfInputSlices(), 7);
  EXPECT_EQ(rec.warnings, 1);
  EXPECT_NE(rec.warningMessages.find("The slices are not evenly spaced: most lie 3.00 mm apart, but 1 gap is wider "
                                     "(6.00 mm between the slices at ("),
    std::string::npos)
    << rec.warningMessages;
  EXPECT_NE(rec.warningMessages.find("as if 1 slice were missing. The volume is interpolated across them"),
    std::string::npos)
    << rec.warningMessages;
  // Still read, at the typical spacing, across the gap.
  EXPECT_EQ(reader->GetOutput()->GetDimensions()[2], 8);
}

TEST(MedicalImageReader, ReadingReportsProgressAndStopsWithAnEmptyVolume)
{
  // The DICOM series (its headers' scan, then the slices) and the gzipped
  // NIfTI report their reading (it was one step, 0 then 1: a folder of
  // hundreds of slices read with the tools' bars standing still). Stopped
  // half way, the reader gives no volume rather than one half read, and the
  // next read is whole.
  for (const std::string& file : { geFolder, lktest::sampleData("cthead/cthead_hu_approx.nii.gz") })
  {
    vtkNew<vtkLKMedicalImageReader> reader;
    reader->SetFileName(file.c_str());
    lktest::ErrorRecorder rec(reader);
    {
      lktest::ProgressRecorder progress(reader);
      reader->Update();
      const auto between = std::count_if(
        progress.progress.begin(), progress.progress.end(), [](double p) { return p > 0.0 && p < 1.0; });
      EXPECT_GE(between, 10) << file;
      EXPECT_GT(reader->GetOutput()->GetNumberOfPoints(), 0) << file;
    }
    vtkMTimeType readTime = reader->GetOutput()->GetMTime();
    {
      lktest::ProgressRecorder progress(reader);
      progress.stopAt = 0.5;
      reader->Modified();
      reader->Update();
      EXPECT_EQ(rec.errors, 0) << rec.messages;
      EXPECT_NE(rec.warningMessages.find("Aborted."), std::string::npos) << file;
      EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0) << file;
      EXPECT_GT(reader->GetOutput()->GetMTime(), readTime);
    }
    reader->Modified();
    reader->Update();
    EXPECT_EQ(rec.errors, 0) << rec.messages;
    EXPECT_GT(reader->GetOutput()->GetNumberOfPoints(), 1000000) << file;
  }
}

TEST(MedicalImageReader, FolderWithoutDicomIsAClearError)
{
  const std::string dir = tempFolder("no-dicom");
  std::ofstream(dir + "/notes.txt") << "not an image\n";
  vtkNew<vtkLKMedicalImageReader> reader;
  lktest::ErrorRecorder rec(reader);
  reader->SetFileName(dir.c_str());
  reader->Update();
  EXPECT_EQ(rec.errors, 1);
  EXPECT_NE(rec.messages.find("no DICOM image series"), std::string::npos) << rec.messages;
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(rec.messages.find("It holds"), std::string::npos) << rec.messages;
}

TEST(MedicalImageReader, AFolderHoldingAVolumeFileNamesIt)
{
  // The bundled CT is a NIfTI beside its licence: given the folder, the user
  // is told which file to give.
  const std::string dir = tempFolder("holds-nifti");
  std::ofstream(dir + "/LICENSE") << "licence\n";
  std::ofstream(dir + "/head.nii.gz") << "x";
  vtkNew<vtkLKMedicalImageReader> reader;
  lktest::ErrorRecorder rec(reader);
  reader->SetFileName(dir.c_str());
  reader->Update();
  EXPECT_EQ(rec.errors, 1);
  EXPECT_NE(rec.messages.find("It holds the volume file '" + dir + "/head.nii.gz': give that file instead"),
    std::string::npos)
    << rec.messages;

  std::ofstream(dir + "/other.NRRD") << "x";
  reader->SetFileName((dir + "/").c_str());
  reader->Update();
  EXPECT_EQ(rec.errors, 2);
  EXPECT_NE(rec.messages.find("the volume files '" + dir + "/head.nii.gz', '" + dir + "/other.NRRD': give one of them"),
    std::string::npos)
    << rec.messages;
}

// DICOM files in a transfer syntax vtkDICOM cannot parse (deflated, as
// gdcmconv --deflated writes them): no series is found, and the message
// says why and how to convert them, instead of "no DICOM image series".
TEST(MedicalImageReader, FilesInAnUnreadableTransferSyntaxAreNamed)
{
  const std::string folder = std::string(LATTICEKIT_TEST_DATA) + "/deflated";
  for (const std::string& input : { folder, folder + "/ct_deflated.dcm" })
  {
    vtkNew<vtkLKMedicalImageReader> reader;
    lktest::ErrorRecorder rec(reader);
    reader->SetFileName(input.c_str());
    reader->Update();
    EXPECT_EQ(rec.errors, 1);
    EXPECT_NE(rec.messages.find("1 of the files looked at is DICOM in the transfer syntax Deflated Explicit VR "
                                "Little Endian (1.2.840.10008.1.2.1.99), which cannot be read here: convert them "
                                "to an uncompressed one first"),
      std::string::npos)
      << rec.messages;
  }
}

// A CT without RescaleIntercept whose values cannot be Hounsfield units
// (air at 0): a warning says an iso value in HU misses the bone. One with
// the intercept but not the slope is rescaled. The phantom (intercept -1024,
// slope 1) gets no warning.
TEST(MedicalImageReader, ACTWhoseValuesAreNotHounsfieldUnitsIsWarnedOf)
{
  vtkNew<vtkLKMedicalImageReader> reader;
  lktest::ErrorRecorder rec(reader);
  reader->SetFileName((std::string(LATTICEKIT_TEST_DATA) + "/ct-no-rescale").c_str());
  reader->Update();
  ASSERT_EQ(rec.errors, 0) << rec.messages;
  EXPECT_EQ(reader->GetOutput()->GetScalarRange()[1], 2000.0);
  EXPECT_NE(rec.warningMessages.find("The CT's images carry no RescaleIntercept, so their stored values are taken "
                                     "as Hounsfield units; but the lowest is 0, where air would be near -1000"),
    std::string::npos)
    << rec.warningMessages;

  // An intercept without its slope: vtkDICOMReader rescales only with both,
  // so the values stayed as stored (air at 0); the intercept is applied with
  // DICOM's slope of 1, with a warning.
  vtkNew<vtkLKMedicalImageReader> noSlope;
  lktest::ErrorRecorder noSlopeRec(noSlope);
  noSlope->SetFileName((std::string(LATTICEKIT_TEST_DATA) + "/ct-no-slope").c_str());
  noSlope->Update();
  ASSERT_EQ(noSlopeRec.errors, 0) << noSlopeRec.messages;
  EXPECT_EQ(noSlope->GetOutput()->GetScalarRange()[0], -1024.0);
  EXPECT_EQ(noSlope->GetOutput()->GetScalarRange()[1], 976.0);
  EXPECT_EQ(noSlopeRec.warnings, 1) << noSlopeRec.warningMessages;
  EXPECT_NE(noSlopeRec.warningMessages.find("The CT's images carry a RescaleIntercept but no RescaleSlope (DICOM "
                                            "requires both): the intercept was applied with a slope of 1."),
    std::string::npos)
    << noSlopeRec.warningMessages;

  vtkNew<vtkLKMedicalImageReader> phantom;
  lktest::ErrorRecorder phantomRec(phantom);
  phantom->SetFileName(lktest::sampleData("dicom-ct-philips-phantom").c_str());
  phantom->Update();
  ASSERT_EQ(phantomRec.errors, 0) << phantomRec.messages;
  EXPECT_EQ(phantomRec.warningMessages.find("RescaleIntercept"), std::string::npos) << phantomRec.warningMessages;
}

TEST(MedicalImageReader, MissingAndCorruptFilesAreClearErrors)
{
  vtkNew<vtkLKMedicalImageReader> reader;
  lktest::ErrorRecorder rec(reader);
  reader->SetFileName("/nonexistent/ct.nrrd");
  reader->Update();
  EXPECT_EQ(rec.errors, 1);
  EXPECT_NE(rec.messages.find("no such file"), std::string::npos);

  // A pipe nobody writes to (opening it waited for ever) and a device that
  // never ends are refused before they are opened.
  const std::string dir = tempFolder("corrupt");
  ASSERT_EQ(mkfifo((dir + "/pipe.nrrd").c_str(), 0600), 0);
  for (const std::string& special : { dir + "/pipe.nrrd", std::string("/dev/zero") })
  {
    vtkNew<vtkLKMedicalImageReader> refused;
    lktest::ErrorRecorder refusedRec(refused);
    refused->SetFileName(special.c_str());
    refused->Update();
    EXPECT_EQ(refusedRec.errors, 1);
    EXPECT_NE(refusedRec.messages.find("it is not a file or a folder but a " +
                std::string(special == "/dev/zero" ? "device" : "pipe")),
      std::string::npos)
      << refusedRec.messages;
  }

  // An NRRD whose data is cut short.
  {
    std::ifstream in(lktest::sampleData("mandible-tcia/test_oncologist_0522c0017_Mandible.nrrd"), std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(dir + "/cut.nrrd", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  }
  rec.errors = 0;
  reader->SetFileName((dir + "/cut.nrrd").c_str());
  reader->Update();
  EXPECT_GE(rec.errors, 1);
  EXPECT_NE(rec.messages.find("Cannot read NRRD"), std::string::npos) << rec.messages;
  EXPECT_EQ(rec.messages.find("vtkNrrdReader.cxx"), std::string::npos) << "vtkNrrdReader's own header in the message: " << rec.messages;

  // A NIfTI file cut short.
  {
    std::ifstream in(lktest::sampleData("cthead/cthead_hu_approx.nii.gz"), std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(dir + "/cut.nii.gz", std::ios::binary) << bytes.substr(0, bytes.size() / 10);
  }
  rec.errors = 0;
  rec.messages.clear();
  reader->SetFileName((dir + "/cut.nii.gz").c_str());
  reader->Update();
  EXPECT_GE(rec.errors, 1);
  EXPECT_NE(rec.messages.find("Cannot read NIfTI file '" + dir + "/cut.nii.gz': NIFTI file is truncated"), std::string::npos)
    << rec.messages;

  // Uncompressed voxels cut short: vtkNrrdReader only warned and
  // vtkMetaImageReader only printed to the terminal, and both returned a
  // volume with zeros where the data was missing. Attached and detached.
  const std::string half(500, '\x7f');
  std::ofstream(dir + "/raw.nrrd", std::ios::binary)
    << "NRRD0004\ntype: unsigned char\ndimension: 3\nsizes: 10 10 10\nencoding: raw\n\n" << half;
  std::ofstream(dir + "/raw.mha", std::ios::binary)
    << "ObjectType = Image\nNDims = 3\nDimSize = 10 10 10\nElementType = MET_UCHAR\nElementDataFile = LOCAL\n" << half;
  std::ofstream(dir + "/voxels.raw", std::ios::binary) << half << half;
  std::ofstream(dir + "/detached.nhdr", std::ios::binary)
    << "NRRD0004\ntype: short\ndimension: 3\nsizes: 10 10 10\nencoding: raw\nendian: little\ndata file: voxels.raw\n\n";
  std::ofstream(dir + "/detached.mhd", std::ios::binary)
    << "ObjectType = Image\nNDims = 3\nDimSize = 10 10 10\nElementType = MET_SHORT\nElementDataFile = voxels.raw\n";
  for (const auto& [file, kind, has, needs] : { std::make_tuple("raw.nrrd", "NRRD", 500, 1000),
         std::make_tuple("raw.mha", "MetaImage", 500, 1000), std::make_tuple("detached.nhdr", "NRRD", 1000, 2000),
         std::make_tuple("detached.mhd", "MetaImage", 1000, 2000) })
  {
    rec.errors = 0;
    rec.messages.clear();
    reader->SetFileName((dir + "/" + file).c_str());
    reader->Update();
    EXPECT_EQ(rec.errors, 1) << file;
    EXPECT_NE(rec.messages.find(std::string("Cannot read ") + kind + " file '" + dir + "/" + file + "': its voxel data has " +
                std::to_string(has) + " bytes where the header asks for " + std::to_string(needs) +
                ": the file is truncated"),
      std::string::npos)
      << rec.messages;
  }
  // The same headers with all their voxels read.
  std::ofstream(dir + "/voxels.raw", std::ios::binary) << half << half << half << half;
  for (const char* file : { "detached.nhdr", "detached.mhd" })
  {
    rec.errors = 0;
    reader->SetFileName((dir + "/" + file).c_str());
    reader->Update();
    EXPECT_EQ(rec.errors, 0) << file << ": " << rec.messages;
    EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 1000) << file;
  }

  // A DICOM series with one file truncated inside its pixel data.
  const std::string series = tempFolder("corrupt-dicom");
  copyGESeries(series);
  {
    std::ifstream in(series + "/10.dcm", std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(series + "/10.dcm", std::ios::binary | std::ios::trunc) << bytes.substr(0, 200000);
  }
  rec.errors = 0;
  reader->SetFileName(series.c_str());
  reader->Update();
  EXPECT_GE(rec.errors, 1);
  EXPECT_NE(rec.messages.find("DICOM"), std::string::npos) << rec.messages;
}

TEST(MedicalImageReader, HeadersThatDescribeNoUsableVolumeAreRefusedBeforeReading)
{
  // A 2-D raw NRRD (vtkNrrdReader crashed reading it) and a header asking for
  // 1e15 voxels (the allocation ended the program): refused from the header.
  const std::string dir = tempFolder("bad-headers");
  const std::string flat = dir + "/slice.nrrd";
  {
    std::ofstream out(flat, std::ios::binary);
    out << "NRRD0004\ntype: float\ndimension: 2\nsizes: 4 4\nencoding: raw\n\n" << std::string(64, '\0');
  }
  const std::string huge = dir + "/huge.nrrd";
  std::ofstream(huge, std::ios::binary)
    << "NRRD0004\ntype: float\ndimension: 3\nsizes: 100000 100000 100000\nencoding: raw\n\n";
  struct Case
  {
    std::string file, message;
  };
  for (const Case& c : { Case{ flat, "at least 2 along each axis" },
         Case{ huge, "more than this machine's memory" } })
  {
    vtkNew<vtkLKMedicalImageReader> reader;
    lktest::ErrorRecorder rec(reader);
    reader->SetFileName(c.file.c_str());
    reader->Update();
    EXPECT_GE(rec.errors, 1) << c.file;
    EXPECT_NE(rec.messages.find(c.message), std::string::npos) << rec.messages;
    EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
  }
}
