#pragma once
/// \file PickLocators.h
/// Fast picking on large surfaces. vtkCellPicker intersects its ray with
/// every cell of every actor whose bounds it crosses: 80 ms a pick on a CT's
/// 600,000-triangle bone surface, so a pen stroke on a whole skull lagged
/// behind the mouse, and a saw line beside the bone (a pick at each pixel
/// of the line) took 20 s to say it missed. With a cell locator per large
/// surface a pick takes a few hundredths of a millisecond.

#include <vtkStaticCellLocator.h>
#include <vtkCellPicker.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkWeakPointer.h>

#include <vector>

namespace lkapp
{

/// The locators a picker uses for the large surfaces of a renderer.
class PickLocators
{
public:
  /// Surfaces of fewer cells keep vtkCellPicker's own exhaustive test (a
  /// few milliseconds there; the same picks as before).
  explicit PickLocators(vtkIdType minimumCells = 50000)
    : minimumCells_(minimumCells)
  {
  }
  /// Gives `picker` a locator (vtkStaticCellLocator: VTK 9.1's
  /// vtkCellLocator returned a hit on the far side of a sphere for one ray
  /// in 10,000) for the data of each visible,
  /// pickable actor of `renderer` with at least minimumCells cells, built
  /// anew for data that changed since the last call, and only those: call it
  /// before each pick (it costs a look at each actor when nothing changed).
  void update(vtkRenderer* renderer, vtkCellPicker* picker);
  /// How many locators the picker was given by the last update.
  std::size_t size() const { return entries_.size(); }

private:
  struct Entry
  {
    vtkWeakPointer<vtkDataSet> data;
    vtkMTimeType time = 0;
    vtkSmartPointer<vtkStaticCellLocator> locator;
  };
  vtkIdType minimumCells_;
  std::vector<Entry> entries_;
};

} // namespace lkapp
