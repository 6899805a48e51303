#include "common/PickLocators.h"

#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkDataSet.h>
#include <vtkMapper.h>

namespace lkapp
{

void PickLocators::update(vtkRenderer* renderer, vtkCellPicker* picker)
{
  std::vector<Entry> kept;
  vtkActorCollection* actors = renderer->GetActors();
  vtkCollectionSimpleIterator it;
  actors->InitTraversal(it);
  while (vtkActor* actor = actors->GetNextActor(it))
  {
    vtkMapper* mapper = actor->GetMapper();
    if (!actor->GetVisibility() || !actor->GetPickable() || !mapper)
      continue;
    mapper->Update(); // a pipeline's output as the picker will see it
    vtkDataSet* data = mapper->GetInput();
    if (!data || data->GetNumberOfCells() < minimumCells_)
      continue;
    bool known = false;
    for (const Entry& e : kept)
      known = known || e.data == data;
    if (known) // two actors of one data set share its locator
      continue;
    Entry entry;
    for (const Entry& e : entries_)
      if (e.data == data && e.time == data->GetMTime())
        entry = e;
    if (!entry.locator)
    {
      entry.data = data;
      entry.time = data->GetMTime();
      entry.locator = vtkSmartPointer<vtkStaticCellLocator>::New();
      entry.locator->SetDataSet(data);
      entry.locator->BuildLocator();
    }
    kept.push_back(entry);
  }
  entries_ = std::move(kept);
  picker->RemoveAllLocators();
  for (const Entry& e : entries_)
    picker->AddLocator(e.locator);
}

} // namespace lkapp
