// The colour scale of a Metro distance picture, shared by the demo and the
// planner: blue (0) to red at `top` (the Metro filter's colour maximum, the
// 99th percentile of the point distances by default), magenta above it, and a
// bar that says so, in mm, dark on a white background.
#ifndef latticekit_apps_DistanceColourBar_h
#define latticekit_apps_DistanceColourBar_h

#include <vtkLookupTable.h>
#include <vtkScalarBarActor.h>
#include <vtkTextProperty.h>

#include <cstdio>

namespace lkapp
{
/// Sets `lut` and `bar` for distances from 0 to `top`; `largest` is the
/// largest distance, shown on the swatch for the points above `top`.
inline void distanceColourBar(double top, double largest, vtkLookupTable* lut, vtkScalarBarActor* bar)
{
  if (!(top > 0.0))
    top = largest > 0.0 ? largest : 1.0;
  lut->SetHueRange(0.667, 0.0);
  lut->SetTableRange(0.0, top);
  lut->SetAboveRangeColor(1.0, 0.0, 1.0, 1.0);
  lut->SetUseAboveRangeColor(largest > top);
  lut->Build();
  bar->SetLookupTable(lut);
  bar->SetTitle("distance (mm)");
  bar->SetNumberOfLabels(5);
  bar->SetMaximumWidthInPixels(90);
  bar->SetDrawAboveRangeSwatch(largest > top);
  char above[64];
  std::snprintf(above, sizeof(above), "up to %.3g", largest);
  bar->SetAboveRangeAnnotation(above);
  bar->SetDrawAnnotations(largest > top);
  for (vtkTextProperty* text :
    { bar->GetLabelTextProperty(), bar->GetTitleTextProperty(), bar->GetAnnotationTextProperty() })
  {
    text->SetColor(0.1, 0.1, 0.1);
    text->ShadowOff();
    text->ItalicOff();
  }
}
} // namespace lkapp

#endif
