// lkapp::showScanPicture: a title longer than the picture is wide breaks
// after its commas, and the legend moves down under it. Renders: run under
// xvfb-run.
#include "common/AppSupport.h"
#include "common/ScanPicture.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPropCollection.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>

#include <gtest/gtest.h>

#include <string>

namespace
{
const char* const kLongTitle = "label map on cut line 1's plane, 3 mm toward the patient's right";

struct Shown
{
  std::string title;
  double titleWidth = 0.0, legendTop = 0.0;
};

/// The picture shown in a square window of `pixels` with the planner's font
/// (12): its title's text and width in pixels, its legend's top (from 0 to 1).
Shown show(const std::string& title, int pixels)
{
  lkapp::ScanPicture picture;
  picture.image = vtkSmartPointer<vtkImageData>::New();
  picture.image->SetDimensions(8, 8, 1);
  picture.image->AllocateScalars(VTK_SHORT, 1);
  picture.side = 40.0;
  picture.title = title;
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkRenderWindow> window;
  window->SetDisplayId(lkapp::openDisplay());
  window->SetOffScreenRendering(1);
  window->SetSize(pixels, pixels);
  window->AddRenderer(renderer);
  lkapp::showScanPicture(renderer, picture, 12);
  window->Render();
  Shown shown;
  vtkPropCollection* props = renderer->GetViewProps();
  props->InitTraversal();
  while (vtkProp* prop = props->GetNextProp())
    if (auto* text = vtkTextActor::SafeDownCast(prop))
    {
      const std::string input = text->GetInput() ? text->GetInput() : "";
      if (input.rfind("label map", 0) == 0)
      {
        shown.title = input;
        double size[2];
        text->GetSize(renderer, size);
        shown.titleWidth = size[0];
      }
      else if (input.rfind("orange", 0) == 0)
        shown.legendTop = text->GetPositionCoordinate()->GetValue()[1];
    }
  return shown;
}
} // namespace

TEST(ScanPictureTitle, ALongTitleBreaksAfterACommaToFitThePicture)
{
  // The planner's view is 370 pixels wide: one line would run out of it.
  const Shown narrow = show(kLongTitle, 370);
  EXPECT_EQ(narrow.title, "label map on cut line 1's plane,\n3 mm toward the patient's right");
  EXPECT_LE(narrow.titleWidth, 0.96 * 370);
  // The exported pictures (600 pixels and more) keep it on one line, the
  // legend where it always stood.
  const Shown wide = show(kLongTitle, 600);
  EXPECT_EQ(wide.title, kLongTitle);
  EXPECT_DOUBLE_EQ(wide.legendTop, 0.935);
  // Under a two-line title the legend stands a line lower (12 points, about
  // 15 pixels of 370).
  EXPECT_LT(narrow.legendTop, 0.935 - 10.0 / 370);
  EXPECT_GT(narrow.legendTop, 0.935 - 30.0 / 370);
}

TEST(ScanPictureTitle, AShortTitleStaysOneLine)
{
  const Shown shown = show("label map on cut line 1's plane", 370);
  EXPECT_EQ(shown.title, "label map on cut line 1's plane");
  EXPECT_DOUBLE_EQ(shown.legendTop, 0.935);
}
