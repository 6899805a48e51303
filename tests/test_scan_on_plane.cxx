// lkapp::viewFrame, scanOnPlane: a plane shown as radiologists show the
// nearest standard plane, and a volume resliced on it exactly where its
// data-to-patient matrix puts it.
#include "common/ScanOnPlane.h"
#include "common/ScanPicture.h"

#include <gtest/gtest.h>

#include <vtkDoubleArray.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkShortArray.h>
#include <vtkSphereSource.h>

#include <cmath>
#include <string>

namespace
{

void expectFrame(const lkapp::ViewFrame& f, const char* right, const char* up, const char* towardViewer)
{
  EXPECT_EQ(std::string(lkapp::directionLetter(f.right)), right);
  EXPECT_EQ(std::string(lkapp::directionLetter(f.up)), up);
  EXPECT_EQ(std::string(lkapp::directionLetter(f.towardViewer)), towardViewer);
  // Right-handed and orthonormal: right x up = toward the viewer.
  std::array<double, 3> cross;
  vtkMath::Cross(f.right.data(), f.up.data(), cross.data());
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(cross[static_cast<std::size_t>(i)], f.towardViewer[static_cast<std::size_t>(i)], 1e-12);
  EXPECT_NEAR(vtkMath::Norm(f.right.data()), 1.0, 1e-12);
  EXPECT_NEAR(vtkMath::Norm(f.up.data()), 1.0, 1e-12);
  EXPECT_NEAR(vtkMath::Dot(f.right.data(), f.up.data()), 0.0, 1e-12);
}

} // namespace

TEST(ScanOnPlane, ShowsPlanesAsRadiologistsDo)
{
  // Axial: from the feet, the front up, the patient's right on the screen's left.
  expectFrame(lkapp::viewFrame({ 0, 0, 0 }, { 0, 0, 1 }), "L", "A", "I");
  expectFrame(lkapp::viewFrame({ 0, 0, 0 }, { 0, 0, -3 }), "L", "A", "I");
  // Coronal: from the front, the head up, the patient's right on the left.
  expectFrame(lkapp::viewFrame({ 0, 0, 0 }, { 0, 1, 0 }), "L", "S", "A");
  // Sagittal: from the left, the head up, the front on the left.
  expectFrame(lkapp::viewFrame({ 0, 0, 0 }, { -2, 0, 0 }), "P", "S", "L");
  // The main job's saw plane across the mandible body: nearest coronal, and
  // its up is the head's direction exactly (the normal has no z).
  const lkapp::ViewFrame saw = lkapp::viewFrame({ 89, 65, 185 }, { -0.55, 0.83, 0 });
  expectFrame(saw, "L", "S", "A");
  EXPECT_NEAR(saw.up[2], 1.0, 1e-12);
  std::array<double, 3> point;
  for (std::size_t i = 0; i < 3; ++i)
    point[i] = saw.centre[i] + 2 * saw.right[i] + 5 * saw.up[i] - 3 * saw.towardViewer[i];
  const auto p = lkapp::inFrame(saw, point);
  EXPECT_NEAR(p[0], 2.0, 1e-12);
  EXPECT_NEAR(p[1], 5.0, 1e-12);
  EXPECT_NEAR(p[2], -3.0, 1e-12);
}

TEST(ScanOnPlane, StandsAsThePlanSaysThePatientLies)
{
  // The bundled CT head: no orientation in its file, its +z to the feet
  // and -y to the face (sample_data/cthead/mandible_plan.json's "patient").
  const lkapp::HeadAndFront headDown{ { 0, 0, -1 }, { 0, -1, 0 } };
  ASSERT_TRUE(lkapp::isValid(headDown));
  const auto expectVector = [](const std::array<double, 3>& v, const std::array<double, 3>& expected) {
    for (std::size_t i = 0; i < 3; ++i)
      EXPECT_NEAR(v[i], expected[i], 1e-12) << "component " << i;
  };
  // Axial: from the feet (+z here), the front (-y) up.
  lkapp::ViewFrame f = lkapp::viewFrame({ 1, 2, 3 }, { 0, 0, 1 }, headDown);
  expectVector(f.towardViewer, { 0, 0, 1 });
  expectVector(f.up, { 0, -1, 0 });
  expectVector(f.centre, { 1, 2, 3 });
  // Coronal: from the front, the head (-z here) up; sagittal: the head up.
  f = lkapp::viewFrame({ 0, 0, 0 }, { 0, 1, 0.2 }, headDown);
  EXPECT_NEAR(f.towardViewer[1], -std::cos(std::atan(0.2)), 1e-12);
  EXPECT_LT(f.up[2], -0.9);
  f = lkapp::viewFrame({ 0, 0, 0 }, { 1, 0, 0 }, headDown);
  expectVector(f.up, { 0, 0, -1 });
  // Right-handed and orthonormal, as the plain frame.
  std::array<double, 3> cross;
  vtkMath::Cross(f.right.data(), f.up.data(), cross.data());
  expectVector(cross, f.towardViewer);
  // The default (an LPS scan's head and front) is the plain frame.
  const lkapp::ViewFrame plain = lkapp::viewFrame({ 0, 0, 0 }, { 0.3, -0.8, 0.4 });
  const lkapp::ViewFrame lps = lkapp::viewFrame({ 0, 0, 0 }, { 0.3, -0.8, 0.4 }, lkapp::HeadAndFront());
  expectVector(lps.right, plain.right);
  expectVector(lps.up, plain.up);
  expectVector(lps.towardViewer, plain.towardViewer);
  // What states no patient: a zero, a NaN, a head along the front.
  EXPECT_FALSE(lkapp::isValid({ { 0, 0, 0 }, { 0, 1, 0 } }));
  EXPECT_FALSE(lkapp::isValid({ { 0, 0, std::nan("") }, { 0, 1, 0 } }));
  EXPECT_FALSE(lkapp::isValid({ { 0, 0, 1 }, { 0, 0.1, -2 } }));
  // ... and falls back to the plain frame.
  const lkapp::ViewFrame fallback = lkapp::viewFrame({ 0, 0, 0 }, { 0.3, -0.8, 0.4 }, { { 0, 0, 1 }, { 0, 0, 1 } });
  expectVector(fallback.up, plain.up);
}

TEST(ScanOnPlane, ReslicesWhereThePatientMatrixPutsTheVolume)
{
  // A volume whose value is a linear function of the patient position
  // (trilinear interpolation gives it exactly): 40 x 30 x 20 voxels of
  // 0.8 x 0.9 x 1.5 mm, its x and y axes turned to -x and -y (an RAS-like
  // file read as LPS) and moved.
  const double spacing[3] = { 0.8, 0.9, 1.5 };
  vtkNew<vtkImageData> volume;
  volume->SetDimensions(40, 30, 20);
  volume->SetSpacing(spacing);
  vtkNew<vtkDoubleArray> values;
  values->SetNumberOfValues(40 * 30 * 20);
  vtkNew<vtkMatrix4x4> toPatient;
  toPatient->SetElement(0, 0, -1.0);
  toPatient->SetElement(1, 1, -1.0);
  toPatient->SetElement(0, 3, 10.0);
  toPatient->SetElement(1, 3, 20.0);
  toPatient->SetElement(2, 3, -30.0);
  const auto field = [](const double p[3]) { return 3.0 * p[0] - 2.0 * p[1] + 0.5 * p[2] + 7.0; };
  for (int k = 0; k < 20; ++k)
    for (int j = 0; j < 30; ++j)
      for (int i = 0; i < 40; ++i)
      {
        const double data[4] = { i * spacing[0], j * spacing[1], k * spacing[2], 1.0 };
        double patient[4];
        toPatient->MultiplyPoint(data, patient);
        values->SetValue(i + 40 * (j + 30 * k), field(patient));
      }
  volume->GetPointData()->SetScalars(values);
  // An oblique plane through the middle of the volume (patient x from -21.2
  // to 10, y from -6.1 to 20, z from -30 to -1.5).
  const lkapp::ViewFrame frame = lkapp::viewFrame({ -5.0, 7.0, -16.0 }, { 0.3, -0.8, 0.4 });
  const double side = 40.0;
  const int pixels = 64;
  auto image = lkapp::scanOnPlane(volume, toPatient, frame, side, pixels, -1000.0);
  ASSERT_NE(image, nullptr);
  int dims[3];
  image->GetDimensions(dims);
  EXPECT_EQ(dims[0], pixels);
  EXPECT_EQ(dims[1], pixels);
  EXPECT_EQ(dims[2], 1);
  const double pixel = side / pixels;
  int inside = 0, outside = 0;
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  for (int j = 0; j < pixels; ++j)
    for (int i = 0; i < pixels; ++i)
    {
      // The pixel's point in the frame, then in the patient.
      double xy[3];
      image->GetPoint(i + pixels * j, xy);
      EXPECT_NEAR(xy[0], -0.5 * side + (i + 0.5) * pixel, 1e-9);
      double patient[4] = { 0, 0, 0, 1 };
      for (int c = 0; c < 3; ++c)
      {
        const std::size_t cc = static_cast<std::size_t>(c);
        patient[c] = frame.centre[cc] + xy[0] * frame.right[cc] + xy[1] * frame.up[cc];
      }
      // Inside the volume's box (a voxel's margin)?
      double data[4];
      vtkNew<vtkMatrix4x4> back;
      vtkMatrix4x4::Invert(toPatient, back);
      back->MultiplyPoint(patient, data);
      const double value = scalars->GetTuple1(i + pixels * j);
      bool in = true, farOut = false;
      const int dimsIn[3] = { 40, 30, 20 };
      for (int c = 0; c < 3; ++c)
      {
        const double extent = (dimsIn[c] - 1) * spacing[c];
        in = in && data[c] >= 0.01 && data[c] <= extent - 0.01;
        farOut = farOut || data[c] < -spacing[c] - 0.01 || data[c] > extent + spacing[c] + 0.01;
      }
      if (in)
      {
        // The reslice computes in float; the field changes 3.6 per mm.
        EXPECT_NEAR(value, field(patient), 1e-3) << "pixel " << i << ", " << j;
        ++inside;
      }
      else if (farOut)
      {
        EXPECT_EQ(value, -1000.0) << "pixel " << i << ", " << j;
        ++outside;
      }
    }
  EXPECT_GT(inside, 1000);
  EXPECT_GT(outside, 100);
}

TEST(ScanOnPlane, RefusesWhatCannotBeResliced)
{
  vtkNew<vtkImageData> empty;
  vtkNew<vtkMatrix4x4> identity;
  const lkapp::ViewFrame frame = lkapp::viewFrame({ 0, 0, 0 }, { 0, 0, 1 });
  EXPECT_EQ(lkapp::scanOnPlane(empty, identity, frame, 10.0, 8, 0.0), nullptr);
  vtkNew<vtkImageData> volume;
  volume->SetDimensions(4, 4, 4);
  volume->AllocateScalars(VTK_SHORT, 1);
  EXPECT_NE(lkapp::scanOnPlane(volume, identity, frame, 10.0, 8, 0.0), nullptr);
  vtkNew<vtkMatrix4x4> flat;
  flat->SetElement(2, 2, 0.0);
  EXPECT_EQ(lkapp::scanOnPlane(volume, flat, frame, 10.0, 8, 0.0), nullptr);
  EXPECT_EQ(lkapp::scanOnPlane(volume, identity, frame, 0.0, 8, 0.0), nullptr);
  EXPECT_EQ(lkapp::scanOnPlane(volume, identity, frame, std::nan(""), 8, 0.0), nullptr);
  EXPECT_EQ(lkapp::scanOnPlane(volume, identity, frame, 10.0, 1, 0.0), nullptr);
  EXPECT_EQ(lkapp::scanOnPlane(volume, nullptr, frame, 10.0, 8, 0.0), nullptr);
}

TEST(ScanOnPlane, GreyWindows)
{
  vtkNew<vtkImageData> labels;
  labels->SetDimensions(3, 1, 1);
  vtkNew<vtkShortArray> v;
  v->SetNumberOfValues(3);
  v->SetValue(0, 0);
  v->SetValue(1, 1);
  v->SetValue(2, 4);
  labels->GetPointData()->SetScalars(v);
  const lkapp::GreyWindow label = lkapp::greyWindowOf(labels, true);
  EXPECT_EQ(label.width, 4.0);
  EXPECT_EQ(label.level, 2.0);
  EXPECT_EQ(lkapp::greyWindowText(label), "");
  const lkapp::GreyWindow ct = lkapp::greyWindowOf(labels, false);
  EXPECT_EQ(ct.width, 2000.0);
  EXPECT_EQ(ct.level, 500.0);
  EXPECT_EQ(lkapp::greyWindowText(ct), " (bone window: W 2000, L 500)");
  const lkapp::GreyWindow soft = lkapp::greyWindowOf(labels, false, true);
  EXPECT_EQ(lkapp::greyWindowText(soft), " (soft-tissue window: W 400, L 40)");
  EXPECT_EQ(lkapp::greyWindowText(lkapp::greyWindowOf(labels, true, true)), ""); // a label map has no soft tissue
  v->SetValue(2, 0);
  v->SetValue(1, 0);
  v->Modified();
  EXPECT_EQ(lkapp::greyWindowOf(labels, true).width, 1.0); // one value: not a zero width
}

TEST(ScanOnPlane, BorderIsWhereThePlaneMeetsTheScansBox)
{
  // Voxel centres from (0, 0, 0) to (10, 20, 30) mm, moved by the matrix to
  // x from -10 to 0 and y from -20 to 0 (turned), z from 100 to 130.
  vtkNew<vtkImageData> volume;
  volume->SetDimensions(11, 21, 31);
  volume->AllocateScalars(VTK_SHORT, 1);
  vtkNew<vtkMatrix4x4> toPatient;
  toPatient->SetElement(0, 0, -1.0);
  toPatient->SetElement(1, 1, -1.0);
  toPatient->SetElement(2, 3, 100.0);
  // An axial plane at z = 105: the box's 10 by 20 mm rectangle, closed.
  auto border = lkapp::scanBorder(volume, toPatient, lkapp::viewFrame({ -5, -10, 105 }, { 0, 0, 1 }));
  ASSERT_EQ(border.size(), 5u);
  EXPECT_EQ(border.front(), border.back());
  double area = 0.0;
  for (std::size_t k = 0; k + 1 < border.size(); ++k)
  {
    EXPECT_NEAR(border[k][2], 105.0, 1e-12);
    EXPECT_TRUE(std::abs(border[k][0]) < 1e-12 || std::abs(border[k][0] + 10) < 1e-12);
    EXPECT_TRUE(std::abs(border[k][1]) < 1e-12 || std::abs(border[k][1] + 20) < 1e-12);
    area += border[k][0] * border[k + 1][1] - border[k + 1][0] * border[k][1];
  }
  EXPECT_NEAR(std::abs(area) / 2, 200.0, 1e-9); // in order around it: no crossed edges
  // A plane that misses the box; one through a corner only.
  EXPECT_TRUE(lkapp::scanBorder(volume, toPatient, lkapp::viewFrame({ 0, 0, 140 }, { 0, 0, 1 })).empty());
  EXPECT_TRUE(lkapp::scanBorder(volume, toPatient, lkapp::viewFrame({ 0, 0, 100 }, { 1, 1, -1 })).empty());
  // A plane that cuts a corner off: a triangle.
  border = lkapp::scanBorder(volume, toPatient, lkapp::viewFrame({ -1, 0, 100 }, { 1, 1, -1 }));
  EXPECT_EQ(border.size(), 4u);
  EXPECT_TRUE(lkapp::scanBorder(nullptr, toPatient, lkapp::viewFrame({ 0, 0, 0 }, { 0, 0, 1 })).empty());
}

TEST(ScanOnPlane, PlaneTracesAcrossThePicture)
{
  // An axial picture 40 mm across at z = 0: right is +x, up is -y (the front).
  const lkapp::ViewFrame frame = lkapp::viewFrame({ 0, 0, 0 }, { 0, 0, 1 });
  auto trace = lkapp::planeTrace(frame, 40.0, { { 5, 0, 0 }, { 1, 0, 0 } });
  ASSERT_EQ(trace.size(), 2u);
  for (const auto& p : trace)
  {
    EXPECT_NEAR(p[0], 5.0, 1e-12);
    EXPECT_NEAR(std::abs(p[1]), 20.0, 1e-12);
    EXPECT_NEAR(p[2], 0.0, 1e-12);
  }
  EXPECT_NEAR(std::abs(trace[0][1] - trace[1][1]), 40.0, 1e-12);
  // A diagonal plane through the middle runs corner to corner.
  trace = lkapp::planeTrace(frame, 40.0, { { 0, 0, 0 }, { 1, 1, 0 } });
  ASSERT_EQ(trace.size(), 2u);
  EXPECT_NEAR(std::sqrt(vtkMath::Distance2BetweenPoints(trace[0].data(), trace[1].data())), 40.0 * std::sqrt(2.0), 1e-9);
  // Beyond the square, or parallel to the picture: nothing.
  EXPECT_TRUE(lkapp::planeTrace(frame, 40.0, { { 30, 0, 0 }, { 1, 0, 0 } }).empty());
  EXPECT_TRUE(lkapp::planeTrace(frame, 40.0, { { 0, 0, 1 }, { 0, 0, 1 } }).empty());
}

TEST(ScanOnPlane, PlanesBesideTheCut)
{
  // A CT whose value is 10 x (patient z) + 3 x (patient y), 1 mm voxels, and a
  // bone ball of radius 5 mm at (0, 0, 0); the cut line a circle of radius 5
  // in the axial plane z = 0.
  vtkNew<vtkImageData> volume;
  volume->SetDimensions(41, 41, 41);
  volume->SetOrigin(-20, -20, -20);
  vtkNew<vtkDoubleArray> values;
  values->SetNumberOfValues(41 * 41 * 41);
  for (int k = 0; k < 41; ++k)
    for (int j = 0; j < 41; ++j)
      for (int i = 0; i < 41; ++i)
        values->SetValue(i + 41 * (j + 41 * k), 10.0 * (k - 20) + 3.0 * (j - 20));
  volume->GetPointData()->SetScalars(values);
  vtkNew<vtkMatrix4x4> identity;
  vtkNew<vtkSphereSource> ball;
  ball->SetRadius(5.0);
  ball->SetThetaResolution(180);
  ball->SetPhiResolution(180);
  ball->Update();
  lkapp::ScanPictureRequest request;
  for (int k = 0; k < 36; ++k)
    request.line.push_back({ 5 * std::cos(k * vtkMath::Pi() / 18), 5 * std::sin(k * vtkMath::Pi() / 18), 0 });
  request.normal = { 0, 0, 1 };
  // 3 mm toward the viewer: an axial plane is seen from the feet, so z = -3.
  request.offset = 3.0;
  lkapp::ScanPicture picture;
  std::string why;
  ASSERT_TRUE(lkapp::makeScanPicture(volume, identity, false, ball->GetOutput(), request, picture, why)) << why;
  EXPECT_NEAR(picture.frame.centre[2], -3.0, 1e-12);
  EXPECT_EQ(lkapp::planeOffsetText(picture.frame, 3.0, true), ", 3 mm toward the feet");
  EXPECT_EQ(lkapp::planeOffsetText(picture.frame, -1.5, true), ", 1.5 mm toward the head");
  EXPECT_EQ(lkapp::planeOffsetText(picture.frame, 3.0, false), ", 3 mm toward the viewer");
  EXPECT_EQ(lkapp::planeOffsetText(picture.frame, -3.0, false), ", 3 mm away from the viewer");
  EXPECT_EQ(lkapp::planeOffsetText(picture.frame, 0.0, true), "");
  // The image is the CT at z = -3: -30 + 3 y at every pixel.
  vtkDataArray* scalars = picture.image->GetPointData()->GetScalars();
  for (vtkIdType p = 0; p < picture.image->GetNumberOfPoints(); p += 37)
  {
    double xy[3];
    picture.image->GetPoint(p, xy);
    const double y = picture.frame.centre[1] + xy[0] * picture.frame.right[1] + xy[1] * picture.frame.up[1];
    if (std::abs(xy[0]) < 19.0 && std::abs(y) < 19.0)
      EXPECT_NEAR(scalars->GetTuple1(p), -30.0 + 3.0 * y, 1e-3) << "pixel " << p;
  }
  // The ball's section there: a circle of radius 4; the cut line stays on
  // its own plane (radius 5, z = 0).
  ASSERT_FALSE(picture.section.empty());
  for (const auto& loop : picture.section)
    for (const auto& q : loop)
    {
      EXPECT_NEAR(q[2], -3.0, 1e-9);
      EXPECT_NEAR(std::hypot(q[0], q[1]), 4.0, 0.02);
    }
  ASSERT_EQ(picture.line.size(), 1u);
  EXPECT_NEAR(picture.line[0][0][0], 5.0, 1e-12);
  EXPECT_EQ(picture.line[0][0][2], 0.0);
  // A window set by hand replaces the preset, rounded; a label map keeps its own.
  EXPECT_EQ(picture.grey.name, "bone window");
  request.windowWidth = 1234.4;
  request.windowLevel = -56.6;
  ASSERT_TRUE(lkapp::makeScanPicture(volume, identity, false, ball->GetOutput(), request, picture, why)) << why;
  EXPECT_EQ(lkapp::greyWindowLabel(picture.grey), "window set by hand: W 1234, L -57");
  EXPECT_EQ(lkapp::handWindow(0.2, 3).width, 1.0); // never a zero width
  // A window dragged far stays one a session reads back.
  EXPECT_EQ(lkapp::greyWindowLabel(lkapp::handWindow(8.04e6, -4.27e6)), "window set by hand: W 100000, L -100000");
  ASSERT_TRUE(lkapp::makeScanPicture(volume, identity, true, ball->GetOutput(), request, picture, why)) << why;
  EXPECT_EQ(lkapp::greyWindowLabel(picture.grey), "");
  // A plane moved by no number is refused.
  request.offset = std::nan("");
  EXPECT_FALSE(lkapp::makeScanPicture(volume, identity, false, ball->GetOutput(), request, picture, why));
  EXPECT_EQ(why, "the plane's offset or the window is not a number");
}
