#include "vtkLKClosedLineCutFilter.h"
#include "vtkLKAbort.h"

#include "latticekit/MeshCut.h"
#include "vtkLKMeshPointIds.h"
#include "vtkLKPolyDataConversion.h"
#include "vtkLKSurfaceAttributes.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
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
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkLKClosedLineCutFilter);

namespace
{
/// Chains line edges into closed loops; a sentence on failure.
std::string loopsOf(const std::vector<lk::EdgeKey>& edges, vtkPolyData* mesh,
  std::vector<std::vector<std::int64_t>>& loops)
{
  // Where a line goes wrong, the point as well as its id: a user finds a
  // place, not a number.
  auto where = [mesh](std::int64_t v) {
    double p[3];
    mesh->GetPoint(static_cast<vtkIdType>(v), p);
    char text[96];
    std::snprintf(text, sizeof(text), " (at %.2f, %.2f, %.2f", p[0], p[1], p[2]);
    return std::to_string(v) + text;
  };
  std::map<std::int64_t, std::vector<std::int64_t>> adj;
  for (const auto& e : edges)
  {
    adj[e.first].push_back(e.second);
    adj[e.second].push_back(e.first);
  }
  for (const auto& [v, n] : adj)
  {
    if (n.size() == 1)
      return "the line is not closed: it ends at mesh point " + where(v) + ")";
    if (n.size() > 2)
      return "lines meet or cross at mesh point " + where(v) + "; " + std::to_string(n.size()) +
        " line edges there); give separate closed loops";
  }
  std::map<std::int64_t, bool> used;
  for (const auto& [start, n] : adj)
  {
    if (used[start])
      continue;
    std::vector<std::int64_t> loop{ start };
    used[start] = true;
    std::int64_t prev = start, cur = n[0];
    while (cur != start)
    {
      loop.push_back(cur);
      used[cur] = true;
      const auto& nn = adj[cur];
      const std::int64_t next = nn[0] == prev ? nn[1] : nn[0];
      prev = cur;
      cur = next;
    }
    loops.push_back(loop);
  }
  return {};
}
} // namespace

vtkLKClosedLineCutFilter::vtkLKClosedLineCutFilter()
{
  this->SetNumberOfInputPorts(2);
}

void vtkLKClosedLineCutFilter::SetLinesConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

void vtkLKClosedLineCutFilter::SetLinesData(vtkPolyData* lines)
{
  this->SetInputData(1, lines);
}

int vtkLKClosedLineCutFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  if (port == 1)
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

int vtkLKClosedLineCutFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* linesIn = vtkPolyData::GetData(inputVector[1]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  this->NumberOfPieces = 0;
  this->NumberOfInnerWallLines = 0;

  vtkNew<vtkPolyData> faces;
  vtkNew<vtkPolyData> ownLines;
  if (input)
  {
    faces->ShallowCopy(input);
    vtkNew<vtkCellArray> none;
    faces->SetLines(none);
  }
  if (input && !linesIn)
  {
    ownLines->SetPoints(input->GetPoints());
    ownLines->SetLines(input->GetLines());
    vtkNew<vtkIdTypeArray> ids;
    ids->SetName("MeshPointId");
    ids->SetNumberOfValues(input->GetNumberOfPoints());
    for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
      ids->SetValue(i, i);
    ownLines->GetPointData()->AddArray(ids);
  }
  lk::PolygonMesh mesh;
  // A mesh without faces (only the lines, say) is named as what the cut
  // needs, not as an empty lattice.
  std::string problem = !input || input->GetNumberOfPolys() == 0
    ? "the mesh has no polygons to cut (it holds " + std::to_string(input ? input->GetNumberOfPoints() : 0) +
      " points and " + std::to_string(input ? input->GetNumberOfLines() : 0) + " line cells" +
      (input && input->GetNumberOfStrips() > 0
          ? ", and " + std::to_string(input->GetNumberOfStrips()) +
            " triangle strips: vtkTriangleFilter turns them into triangles)"
          : std::string(")"))
    : lkvtk::toPolygonMesh(faces, mesh);
  std::vector<lk::EdgeKey> edges;
  std::vector<std::vector<std::int64_t>> loops;
  if (problem.empty())
    problem = lkvtk::lineEdges(linesIn ? linesIn : ownLines.Get(), input, edges);
  if (problem.empty() && linesIn)
    if (const std::string off = lkvtk::linesOffTheirMeshPoints(linesIn, input); !off.empty())
      vtkWarningMacro("The lines may belong to another mesh: " << off << ". They are taken by their MeshPointIds.");
  if (problem.empty() && edges.empty())
    problem = "no closed line to cut along (give input 1, or line cells on the mesh)";
  if (problem.empty())
    problem = loopsOf(edges, input, loops);
  if (!problem.empty())
  {
    vtkErrorMacro("Cannot cut: " << problem << ".");
    return 0;
  }
  lk::CutResult cut;
  try
  {
    cut = lk::cutAlongLoops(mesh, loops, this->Capping, this->CutInnerWalls);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Cannot cut: " << e.what() << ".");
    return 0;
  }
  for (const std::size_t l : cut.loopsInOnePiece)
  {
    if (l >= loops.size())
      continue; // an inner-wall line the filter added
    const auto v = static_cast<vtkIdType>(loops[l].front());
    double x[3];
    input->GetPoint(v, x);
    vtkWarningMacro(<< "A line of " << loops[l].size() << " mesh points (through mesh point " << v << " at " << x[0]
                    << ", " << x[1] << ", " << x[2]
                    << ") separates nothing: the bone joins around it (a ring or a handle joins its two sides), "
                       "so it stays a slit in one piece, with its two caps back to back.");
  }
  for (std::size_t p = 0; p < cut.capCrossings.size(); ++p)
    if (cut.capCrossings[p] > 0)
      vtkWarningMacro(<< "Piece " << p << ": its cap crosses the surface or another cap (" << cut.capCrossings[p]
                      << " pairs of triangles intersect, reaching at most " << cut.capCrossingDepths[p]
                      << " through each other), so the piece is not a valid solid. A cap crosses the "
                         "surface where a line is far from planar, and two caps overlap where nested lines could "
                         "not share one cap.");
  if (cut.emptyPieces > 0)
    vtkWarningMacro(<< cut.emptyPieces << (cut.emptyPieces == 1 ? " region" : " regions")
                    << " between the lines held only faces that their cap covers exactly (a line around one or two "
                       "triangles encloses nothing): no piece for them.");
  for (std::size_t p = 0; p < cut.capNonManifoldEdges.size(); ++p)
    if (cut.capNonManifoldEdges[p] > 0)
      vtkWarningMacro(<< "Piece " << p << ": " << cut.capNonManifoldEdges[p]
                      << " edges at its cap are shared by more than two faces, so the piece is not a manifold "
                         "solid (field data CapNonManifoldEdges).");
  this->UpdateProgress(0.8);
  if (lkvtk::stopRequested(this, { output }))
    return 1;

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIdTypeArray> pointOrigin, cellOrigin;
  pointOrigin->SetName("InputPointId");
  cellOrigin->SetName("InputCellId");
  vtkNew<vtkIntArray> region;
  region->SetName("RegionId");
  vtkNew<vtkUnsignedCharArray> capFlag;
  capFlag->SetName("Cap");
  const vtkIdType firstPoly = input->GetNumberOfVerts() + input->GetNumberOfLines();
  vtkIdType totalPoints = 0, totalFaces = 0, totalCorners = 0;
  for (const auto& piece : cut.pieces)
  {
    totalPoints += static_cast<vtkIdType>(piece.points.size());
    totalFaces += static_cast<vtkIdType>(piece.faces.size());
    for (const auto& face : piece.faces)
      totalCorners += static_cast<vtkIdType>(face.size());
  }
  points->SetNumberOfPoints(totalPoints);
  pointOrigin->SetNumberOfValues(totalPoints);
  polys->AllocateExact(totalFaces, totalCorners);
  cellOrigin->SetNumberOfValues(totalFaces);
  region->SetNumberOfValues(totalFaces);
  capFlag->SetNumberOfValues(totalFaces);
  vtkIdType base = 0, cell = 0;
  std::vector<vtkIdType> ids;
  for (std::size_t p = 0; p < cut.pieces.size(); ++p)
  {
    for (std::size_t v = 0; v < cut.pieces[p].points.size(); ++v)
    {
      const vtkIdType id = base + static_cast<vtkIdType>(v);
      points->SetPoint(id, cut.pieces[p].points[v].data());
      pointOrigin->SetValue(id, static_cast<vtkIdType>(cut.vertexOrigin[p][v]));
    }
    for (std::size_t f = 0; f < cut.pieces[p].faces.size(); ++f, ++cell)
    {
      const auto& face = cut.pieces[p].faces[f];
      ids.clear();
      for (auto v : face)
        ids.push_back(base + static_cast<vtkIdType>(v));
      polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
      const auto origin = cut.faceOrigin[p][f];
      cellOrigin->SetValue(cell, origin < 0 ? -1 : firstPoly + static_cast<vtkIdType>(origin));
      region->SetValue(cell, static_cast<int>(p));
      capFlag->SetValue(cell, origin < 0 ? 1 : 0);
    }
    base += static_cast<vtkIdType>(cut.pieces[p].points.size());
  }
  output->SetPoints(points);
  output->SetPolys(polys);
  // The input's attributes, as VTK's clip filters carry them; cap points and
  // cap faces, which have no input counterpart, get the arrays' null value.
  lkvtk::carryByOrigin(input->GetPointData(), output->GetPointData(), pointOrigin);
  lkvtk::carryByOrigin(input->GetCellData(), output->GetCellData(), cellOrigin);
  output->GetPointData()->AddArray(pointOrigin);
  output->GetCellData()->AddArray(cellOrigin);
  output->GetCellData()->AddArray(region);
  output->GetCellData()->AddArray(capFlag);
  vtkNew<vtkDoubleArray> count;
  count->SetName("Pieces");
  count->InsertNextValue(static_cast<double>(cut.pieces.size()));
  output->GetFieldData()->AddArray(count);
  vtkNew<vtkDoubleArray> innerLines;
  innerLines->SetName("InnerWallLines");
  innerLines->InsertNextValue(static_cast<double>(cut.innerWallLoops));
  output->GetFieldData()->AddArray(innerLines);
  if (!cut.capCrossings.empty())
  {
    vtkNew<vtkDoubleArray> crossings; // one value per piece
    crossings->SetName("CapCrossings");
    for (const std::size_t c : cut.capCrossings)
      crossings->InsertNextValue(static_cast<double>(c));
    output->GetFieldData()->AddArray(crossings);
    vtkNew<vtkDoubleArray> depths; // one value per piece
    depths->SetName("CapCrossingDepth");
    for (const double d : cut.capCrossingDepths)
      depths->InsertNextValue(d);
    output->GetFieldData()->AddArray(depths);
    vtkNew<vtkDoubleArray> nonManifold; // one value per piece
    nonManifold->SetName("CapNonManifoldEdges");
    for (const std::size_t n : cut.capNonManifoldEdges)
      nonManifold->InsertNextValue(static_cast<double>(n));
    output->GetFieldData()->AddArray(nonManifold);
  }
  {
    vtkNew<vtkDoubleArray> slits; // lines that separate nothing
    slits->SetName("LinesInOnePiece");
    slits->InsertNextValue(static_cast<double>(
      std::count_if(cut.loopsInOnePiece.begin(), cut.loopsInOnePiece.end(), [&](std::size_t l) { return l < loops.size(); })));
    output->GetFieldData()->AddArray(slits);
  }
  this->NumberOfPieces = static_cast<int>(cut.pieces.size());
  this->NumberOfInnerWallLines = static_cast<int>(cut.innerWallLoops);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkLKClosedLineCutFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Capping: " << this->Capping << "\n";
  os << indent << "CutInnerWalls: " << this->CutInnerWalls << "\n";
}
