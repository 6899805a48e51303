// lkapp::useFontFor: names in scripts VTK's compiled fonts lack are drawn
// with an installed font (fontconfig), and Latin names keep VTK's font.
// Renders: run under xvfb-run. Needs the fonts scripts/setup.sh installs
// (fonts-dejavu-core, fonts-droid-fallback).
#include "common/AppSupport.h"
#include "common/TextFont.h"

#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>
#include <vtksys/SystemTools.hxx>

#include <gtest/gtest.h>

#include <string>

namespace
{
/// How many pixels `text` darkens, drawn black on white at 24 points in a
/// 400 x 80 window with `property`'s font.
int inkOf(const std::string& text, vtkTextProperty* property)
{
  vtkNew<vtkTextActor> actor;
  actor->SetInput(text.c_str());
  actor->GetTextProperty()->ShallowCopy(property);
  actor->GetTextProperty()->SetFontSize(24);
  actor->GetTextProperty()->SetColor(0, 0, 0);
  actor->SetPosition(10, 20);
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(1, 1, 1);
  renderer->AddActor2D(actor);
  vtkNew<vtkRenderWindow> window;
  window->SetDisplayId(lkapp::openDisplay());
  window->SetOffScreenRendering(1);
  window->SetSize(400, 80);
  window->AddRenderer(renderer);
  window->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->Update();
  vtkUnsignedCharArray* rgb = vtkUnsignedCharArray::SafeDownCast(grab->GetOutput()->GetPointData()->GetScalars());
  int ink = 0;
  for (vtkIdType i = 0; i < rgb->GetNumberOfTuples(); ++i)
    ink += rgb->GetValue(3 * i) < 128 ? 1 : 0;
  return ink;
}
} // namespace

TEST(TextFont, LatinNamesKeepVTKsCompiledFont)
{
  vtkNew<vtkTextProperty> property;
  for (const std::string text : { "piece 0", "Sch\u00e4del", "\u010Celist", "\u0141\u00f3d\u017a \u2014 \u20ac" })
  {
    EXPECT_EQ(lkapp::useFontFor(property, text), "") << text;
    EXPECT_EQ(property->GetFontFamily(), VTK_ARIAL) << text;
  }
}

TEST(TextFont, CyrillicIsDrawnWithAnInstalledFont)
{
  const std::string name = "\u0427\u0435\u043b\u044e\u0441\u0442\u044c"; // Челюсть
  vtkNew<vtkTextProperty> compiled;
  // The problem: VTK's compiled Arial leaves every letter out.
  EXPECT_EQ(inkOf(name, compiled), 0);
  vtkNew<vtkTextProperty> property;
  property->BoldOn();
  EXPECT_EQ(lkapp::useFontFor(property, name), "");
  ASSERT_EQ(property->GetFontFamily(), VTK_FONT_FILE);
  ASSERT_NE(property->GetFontFile(), nullptr);
  EXPECT_TRUE(vtksys::SystemTools::FileExists(property->GetFontFile(), true)) << property->GetFontFile();
  EXPECT_GT(inkOf(name, property), 100);
  // A Latin text after it goes back to the compiled font.
  EXPECT_EQ(lkapp::useFontFor(property, "piece 1"), "");
  EXPECT_EQ(property->GetFontFamily(), VTK_ARIAL);
}

TEST(TextFont, GreekAndKanjiAreDrawn)
{
  for (const std::string name : { "\u039a\u03ac\u03c4\u03c9 \u03b3\u03bd\u03ac\u03b8\u03bf\u03c2", "\u4e0b\u984e\u9aa8" })
  {
    vtkNew<vtkTextProperty> property;
    EXPECT_EQ(lkapp::useFontFor(property, name), "") << name;
    EXPECT_EQ(property->GetFontFamily(), VTK_FONT_FILE) << name;
    EXPECT_GT(inkOf(name, property), 100) << name;
  }
}

TEST(TextFont, CharactersNoFontHasAreReturned)
{
  // A private-use code point: no font has it, so the text keeps the
  // compiled font and the caller hears which character is left out.
  vtkNew<vtkTextProperty> property;
  const std::string unknown = "\U0010FFFD";
  EXPECT_EQ(lkapp::useFontFor(property, "bone " + unknown), unknown);
  EXPECT_EQ(property->GetFontFamily(), VTK_ARIAL);
}
