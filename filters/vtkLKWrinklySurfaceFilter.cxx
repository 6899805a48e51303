#include "vtkLKWrinklySurfaceFilter.h"
#include "vtkLKAbort.h"
#include "vtkLKPolyDataConversion.h"

#include "latticekit/WrinklySurface.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkLKWrinklySurfaceFilter);

int vtkLKWrinklySurfaceFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  // Other cells first: they would be left out without a word.
  if (input && input->GetNumberOfPoints() > 0)
    if (const std::string other = lkvtk::otherThanPolygons(input); !other.empty())
    {
      vtkErrorMacro("Cannot build a wrinkly surface: the control mesh is made of polygons, but this one has "
        << other << ".");
      return 0;
    }
  if (!input || input->GetNumberOfPoints() == 0 || input->GetNumberOfPolys() == 0)
  {
    vtkErrorMacro("Cannot build a wrinkly surface: the control mesh has no points or no polygons.");
    return 0;
  }
  vtkPointData* pd = input->GetPointData();
  vtkDataArray* heights = pd->GetArray(this->HeightArrayName.c_str());
  if (!heights || heights->GetNumberOfComponents() != 1)
  {
    vtkErrorMacro("Cannot build a wrinkly surface: the control mesh needs a one-component point array \""
      << this->HeightArrayName << "\" with the heights.");
    return 0;
  }
  vtkDataArray* colors = pd->GetArray(this->ColorArrayName.c_str());
  if (colors && colors->GetNumberOfComponents() != 3)
  {
    vtkErrorMacro("The colour array \"" << this->ColorArrayName << "\" must have 3 components, not "
                                        << colors->GetNumberOfComponents() << ".");
    return 0;
  }
  vtkDataArray* opacity = pd->GetArray(this->OpacityArrayName.c_str());
  if (opacity && opacity->GetNumberOfComponents() != 1)
  {
    vtkErrorMacro("The opacity array \"" << this->OpacityArrayName << "\" must have 1 component.");
    return 0;
  }
  vtkDataArray* isVirtual = pd->GetArray(this->VirtualArrayName.c_str());

  lk::WrinklyControlMesh mesh;
  const vtkIdType np = input->GetNumberOfPoints();
  mesh.points.resize(static_cast<std::size_t>(np));
  mesh.heights.resize(static_cast<std::size_t>(np));
  mesh.attributeComponents = (colors ? 3 : 0) + (opacity ? 1 : 0);
  mesh.attributes.reserve(static_cast<std::size_t>(np) * mesh.attributeComponents);
  double colorScale = 1.0;
  if (colors)
  {
    double largest = 0.0;
    for (int c = 0; c < 3; ++c)
      largest = std::max(largest, colors->GetRange(c)[1]);
    colorScale = largest > 1.0 ? 1.0 / 255.0 : 1.0; // 0..255 colours
  }
  for (vtkIdType i = 0; i < np; ++i)
  {
    double p[3];
    input->GetPoint(i, p);
    mesh.points[static_cast<std::size_t>(i)] = lk::Vec3(p[0], p[1], p[2]);
    mesh.heights[static_cast<std::size_t>(i)] = heights->GetComponent(i, 0);
    if (colors)
      for (int c = 0; c < 3; ++c)
        mesh.attributes.push_back(colors->GetComponent(i, c) * colorScale);
    if (opacity)
      mesh.attributes.push_back(opacity->GetComponent(i, 0));
    if (isVirtual)
      mesh.isVirtual.push_back(isVirtual->GetComponent(i, 0) != 0.0 ? 1 : 0);
  }
  auto it = vtk::TakeSmartPointer(input->GetPolys()->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n;
    const vtkIdType* ids;
    it->GetCurrentCell(n, ids);
    mesh.faces.emplace_back(ids, ids + n);
  }
  this->UpdateProgress(0.05);

  lk::WrinklyTessellation t;
  try
  {
    lk::WrinklyParameters params;
    params.shuffleU = this->ShuffleU;
    params.shuffleV = this->ShuffleV;
    params.iterations = this->Iterations;
    params.alpha0 = this->Alpha0;
    params.alpha1 = this->Alpha1;
    if (this->SamplingTolerance < 0.0 || std::isnan(this->SamplingTolerance))
    {
      vtkErrorMacro("SamplingTolerance must be 0 (use Iterations) or a positive length.");
      return 0;
    }
    if (this->SamplingTolerance > 0.0)
      params.iterations = 0; // Iterations is ignored; the tolerance picks K below
    lk::WrinklySurface surface(mesh, params);
    if (this->SamplingTolerance > 0.0)
      surface.setIterations(lk::wrinklyIterationsForTolerance(surface, this->SamplingTolerance));
    params.iterations = surface.parameters().iterations;
    this->UsedIterations = params.iterations;
    int resolution = this->Resolution;
    if (resolution == 0)
    {
      resolution = 1;
      const int n = 2 * std::max(params.shuffleU, params.shuffleV) + 1;
      for (int k = 0; k < params.iterations && resolution <= 4096 / n; ++k)
        resolution *= n;
    }
    bool aborted = false;
    t = lk::tessellateWrinkly(surface, resolution, [&](double f) {
      this->UpdateProgress(0.05 + 0.85 * f);
      aborted = this->GetAbortExecute() != 0;
      return !aborted;
    });
    if (aborted && lkvtk::stopRequested(this, { output }))
      return 1;
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Cannot build a wrinkly surface: " << e.what() << ".");
    return 0;
  }

  const auto nOut = static_cast<vtkIdType>(t.points.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(nOut);
  vtkNew<vtkDoubleArray> h, normals;
  h->SetName("Height");
  h->SetNumberOfTuples(nOut);
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(nOut);
  for (vtkIdType i = 0; i < nOut; ++i)
  {
    const auto& p = t.points[static_cast<std::size_t>(i)];
    points->SetPoint(i, p.x(), p.y(), p.z());
    h->SetValue(i, t.heights[static_cast<std::size_t>(i)]);
    const auto& n = t.normals[static_cast<std::size_t>(i)];
    normals->SetTuple3(i, n.x(), n.y(), n.z());
  }
  vtkNew<vtkCellArray> tris;
  vtkNew<vtkIdTypeArray> owner;
  owner->SetName("ControlPointId");
  tris->AllocateExact(static_cast<vtkIdType>(t.triangles.size()), 3 * static_cast<vtkIdType>(t.triangles.size()));
  for (std::size_t k = 0; k < t.triangles.size(); ++k)
  {
    const vtkIdType ids[3] = { t.triangles[k][0], t.triangles[k][1], t.triangles[k][2] };
    tris->InsertNextCell(3, ids);
    owner->InsertNextValue(t.trianglePoint[k]);
  }
  output->SetPoints(points);
  output->SetPolys(tris);
  output->GetPointData()->AddArray(h);
  output->GetPointData()->SetNormals(normals);
  output->GetCellData()->AddArray(owner);
  const int ac = mesh.attributeComponents;
  if (ac > 0)
  {
    vtkNew<vtkUnsignedCharArray> rendered;
    rendered->SetName("Colors");
    rendered->SetNumberOfComponents(opacity ? 4 : 3);
    vtkSmartPointer<vtkDataArray> colorOut, opacityOut;
    if (colors)
    {
      colorOut = vtk::TakeSmartPointer(colors->NewInstance());
      colorOut->SetName(colors->GetName());
      colorOut->SetNumberOfComponents(3);
      colorOut->SetNumberOfTuples(nOut);
      rendered->SetNumberOfTuples(nOut);
    }
    if (opacity)
    {
      opacityOut = vtk::TakeSmartPointer(opacity->NewInstance());
      opacityOut->SetName(opacity->GetName());
      opacityOut->SetNumberOfTuples(nOut);
    }
    for (vtkIdType i = 0; i < nOut; ++i)
    {
      const double* a = &t.attributes[static_cast<std::size_t>(i) * ac];
      if (colors)
      {
        for (int c = 0; c < 3; ++c)
        {
          colorOut->SetComponent(i, c, a[c] / colorScale);
          rendered->SetComponent(i, c, std::clamp(std::round(a[c] * 255.0), 0.0, 255.0));
        }
        if (opacity)
          rendered->SetComponent(i, 3, std::clamp(std::round(a[3] * 255.0), 0.0, 255.0));
      }
      if (opacity)
        opacityOut->SetComponent(i, 0, a[colors ? 3 : 0]);
    }
    if (colors)
    {
      output->GetPointData()->AddArray(colorOut);
      output->GetPointData()->SetScalars(rendered);
    }
    if (opacity)
      output->GetPointData()->AddArray(opacityOut);
  }
  vtkNew<vtkIntArray> used;
  used->SetName("Iterations");
  used->InsertNextValue(this->UsedIterations);
  output->GetFieldData()->AddArray(used);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkLKWrinklySurfaceFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ShuffleU: " << this->ShuffleU << "\n";
  os << indent << "ShuffleV: " << this->ShuffleV << "\n";
  os << indent << "Iterations: " << this->Iterations << "\n";
  os << indent << "SamplingTolerance: " << this->SamplingTolerance << "\n";
  os << indent << "Alpha0: " << this->Alpha0 << "\n";
  os << indent << "Alpha1: " << this->Alpha1 << "\n";
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "HeightArrayName: " << this->HeightArrayName << "\n";
  os << indent << "ColorArrayName: " << this->ColorArrayName << "\n";
  os << indent << "OpacityArrayName: " << this->OpacityArrayName << "\n";
  os << indent << "VirtualArrayName: " << this->VirtualArrayName << "\n";
}
