// A sphere's triangles taken as a lattice, its smooth surface, and the Metro
// distance between the two: a pipeline of installed latticekit filters.
#include <vtkLKLatticeSurfaceFilter.h>
#include <vtkLKMetroFilter.h>

#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkSphereSource.h>

#include <cmath>
#include <iostream>

int main()
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(10);
  sphere->SetThetaResolution(12);
  sphere->SetPhiResolution(8);
  vtkNew<vtkLKLatticeSurfaceFilter> surface;
  surface->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkLKMetroFilter> metro;
  metro->SetInputConnection(0, surface->GetOutputPort());
  metro->SetInputConnection(1, sphere->GetOutputPort());
  metro->Update();
  vtkPolyData* out = metro->GetOutput();
  vtkDataArray* hausdorff = out->GetFieldData()->GetArray("Hausdorff_Max");
  const double h = hausdorff ? hausdorff->GetTuple1(0) : NAN;
  std::cout << "surface: " << surface->GetOutput()->GetNumberOfCells() << " triangles, Hausdorff " << h << "\n";
  // The rounded surface lies inside the sphere's facets, a fraction of the
  // radius away.
  return surface->GetOutput()->GetNumberOfCells() > 0 && h > 0 && h < 2 ? 0 : 1;
}
