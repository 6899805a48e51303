#include "vtkLKWrinklyNetSource.h"

#include "latticekit/WrinklyNets.h"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkLKWrinklyNetSource);

vtkLKWrinklyNetSource::vtkLKWrinklyNetSource()
{
  this->SetNumberOfInputPorts(0);
}

int vtkLKWrinklyNetSource::RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (std::isnan(this->Spacing) || !std::isfinite(this->HeightAmplitude))
  {
    vtkErrorMacro("Spacing and HeightAmplitude must be finite numbers, not " << this->Spacing << " and "
                                                                              << this->HeightAmplitude << ".");
    return 0;
  }
  lk::WrinklyNetStyle style;
  style.spacing = this->Spacing;
  style.heightAmplitude = this->HeightAmplitude;
  style.seed = static_cast<unsigned>(this->Seed);
  lk::WrinklyControlMesh m;
  try
  {
    switch (this->NetType)
    {
      case Polygon: m = lk::wrinklyPolygonNet(this->Sides, this->Rings, this->EdgeCells, style); break;
      case Annular: m = lk::wrinklyAnnularNet(this->Spokes, std::max(2, this->Rings), style); break;
      default: m = lk::wrinklyRegularNet(this->CellsU, this->CellsV, style); break;
    }
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Cannot make the net: " << e.what() << ".");
    return 0;
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkDoubleArray> heights, rgb;
  heights->SetName("Height");
  rgb->SetName("RGB");
  rgb->SetNumberOfComponents(3);
  for (std::size_t i = 0; i < m.points.size(); ++i)
  {
    points->InsertNextPoint(m.points[i].data());
    heights->InsertNextValue(m.heights[i]);
    rgb->InsertNextTuple(&m.attributes[i * 3]);
  }
  vtkNew<vtkCellArray> polys;
  for (const auto& f : m.faces)
  {
    std::vector<vtkIdType> ids(f.begin(), f.end());
    polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  output->SetPoints(points);
  output->SetPolys(polys);
  output->GetPointData()->AddArray(heights);
  output->GetPointData()->AddArray(rgb);
  return 1;
}

void vtkLKWrinklyNetSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NetType: " << this->NetType << "\n";
  os << indent << "CellsU: " << this->CellsU << " CellsV: " << this->CellsV << "\n";
  os << indent << "Sides: " << this->Sides << " Rings: " << this->Rings << " EdgeCells: " << this->EdgeCells
     << " Spokes: " << this->Spokes << "\n";
  os << indent << "Spacing: " << this->Spacing << " HeightAmplitude: " << this->HeightAmplitude
     << " Seed: " << this->Seed << "\n";
}
