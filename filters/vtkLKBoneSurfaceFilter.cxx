#include "vtkLKBoneSurfaceFilter.h"
#include "vtkLKAbort.h"
#include "vtkLKProgressRelay.h"

#include "vtkLKMeshRepairFilter.h"
#include "vtkLKOpenEdges.h"

#include "latticekit/CavityFill.h"

#include <vtkAbstractArray.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkExtractVOI.h>
#include <vtkFlyingEdges3D.h>
#include <vtkMassProperties.h>
#include <vtkImageCast.h>
#include <vtkImageConstantPad.h>
#include <vtkImageData.h>
#include <vtkImageGaussianSmooth.h>
#include <vtkInformation.h>
#include <vtkInformationVector.h>
#include <vtkMatrix3x3.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataConnectivityFilter.h>
#include <vtkReverseSense.h>
#include <vtkStringArray.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtkWindowedSincPolyDataFilter.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <exception>
#include <set>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkLKBoneSurfaceFilter);

namespace
{
/// The voxel extent that holds the crop box (patient coordinates) of
/// `image`, whose data-to-patient matrix is `patient`; a problem, or "".
std::string cropExtent(vtkImageData* image, vtkMatrix4x4* patient, const double box[6], int v[6])
{
  for (int c = 0; c < 3; ++c)
    if (!std::isfinite(box[2 * c]) || !std::isfinite(box[2 * c + 1]) || !(box[2 * c] < box[2 * c + 1]))
      return "the crop box must be (xmin, xmax, ymin, ymax, zmin, zmax), finite, each min below its max";
  vtkNew<vtkMatrix4x4> toData;
  vtkMatrix4x4::Invert(patient, toData);
  double lo[3] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double hi[3] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (int corner = 0; corner < 8; ++corner)
  {
    const double p[4] = { box[(corner & 1) ? 1 : 0], box[(corner & 2) ? 3 : 2], box[(corner & 4) ? 5 : 4], 1.0 };
    double d[4];
    toData->MultiplyPoint(p, d);
    for (int c = 0; c < 3; ++c)
    {
      lo[c] = std::min(lo[c], d[c]);
      hi[c] = std::max(hi[c], d[c]);
    }
  }
  int e[6];
  double origin[3], spacing[3];
  image->GetExtent(e);
  image->GetOrigin(origin);
  image->GetSpacing(spacing);
  for (int c = 0; c < 3; ++c)
  {
    // Clamped as doubles first: a box far outside would overflow the int.
    const double a = std::floor((lo[c] - origin[c]) / spacing[c]);
    const double b = std::ceil((hi[c] - origin[c]) / spacing[c]);
    v[2 * c] = static_cast<int>(std::max<double>(e[2 * c], std::min<double>(e[2 * c + 1], a)));
    v[2 * c + 1] = static_cast<int>(std::max<double>(e[2 * c], std::min<double>(e[2 * c + 1], b)));
    if (!(a < e[2 * c + 1]) || !(b > e[2 * c]) || v[2 * c] >= v[2 * c + 1])
      return "the crop box misses the volume (the box is in patient coordinates, mm, as the surface is)";
  }
  return {};
}

/// The voxels of `image` (one component) whose value is not `background`,
/// as an extent; false where there are none.
template <typename T>
bool contentOf(const T* v, const int dims[3], T background, int box[6])
{
  int lo[3] = { dims[0], dims[1], dims[2] }, hi[3] = { -1, -1, -1 };
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j, v += dims[0])
    {
      int first = 0;
      while (first < dims[0] && v[first] == background)
        ++first;
      if (first == dims[0])
        continue;
      int last = dims[0] - 1;
      while (v[last] == background)
        --last;
      lo[0] = std::min(lo[0], first);
      hi[0] = std::max(hi[0], last);
      lo[1] = std::min(lo[1], j);
      hi[1] = std::max(hi[1], j);
      lo[2] = std::min(lo[2], k);
      hi[2] = std::max(hi[2], k);
    }
  for (int a = 0; a < 3; ++a)
  {
    box[2 * a] = lo[a];
    box[2 * a + 1] = hi[a];
  }
  return hi[0] >= 0;
}

bool contentExtent(vtkImageData* image, double background, int extent[6])
{
  int dims[3], box[6];
  image->GetDimensions(dims);
  image->GetExtent(extent);
  bool found = false;
  switch (image->GetScalarType())
  {
    vtkTemplateMacro(found = contentOf(static_cast<const VTK_TT*>(image->GetScalarPointer()), dims,
                       static_cast<VTK_TT>(background), box));
    default:
      return false;
  }
  for (int a = 0; found && a < 3; ++a)
  {
    extent[2 * a + 1] = extent[2 * a] + box[2 * a + 1];
    extent[2 * a] += box[2 * a];
  }
  return found;
}

/// The voxels of a label map at 0.5 or above (its label's).
vtkIdType labelledVoxels(vtkImageData* image)
{
  vtkDataArray* values = image->GetPointData()->GetScalars();
  const vtkIdType count = values->GetNumberOfTuples();
  if (values->GetDataType() == VTK_UNSIGNED_CHAR && values->GetNumberOfComponents() == 1)
  {
    const auto* v = static_cast<const unsigned char*>(values->GetVoidPointer(0));
    return static_cast<vtkIdType>(std::count_if(v, v + count, [](unsigned char x) { return x != 0; }));
  }
  vtkIdType labelled = 0;
  for (vtkIdType v = 0; v < count; ++v)
    labelled += values->GetComponent(v, 0) >= 0.5;
  return labelled;
}

bool isBinaryLabelMap(vtkImageData* image)
{
  vtkDataArray* s = image->GetPointData()->GetScalars();
  if (!s || s->GetDataType() == VTK_FLOAT || s->GetDataType() == VTK_DOUBLE)
  {
    return false;
  }
  double range[2];
  s->GetRange(range);
  if (!(range[0] == 0.0 && range[1] == 1.0))
  {
    return false;
  }
  return true; // an integer array whose range is [0, 1] has only 0 and 1
}

/// The distinct values of an integer array's component, in order, or nothing
/// when it holds floating-point values or more than `most` distinct ones.
std::vector<long long> fewIntegerValues(vtkDataArray* s, std::size_t most, int component = 0)
{
  if (!s || s->GetDataType() == VTK_FLOAT || s->GetDataType() == VTK_DOUBLE)
    return {};
  std::set<long long> seen;
  const vtkIdType n = s->GetNumberOfTuples();
  for (vtkIdType i = 0; i < n; ++i)
  {
    seen.insert(static_cast<long long>(s->GetComponent(i, component)));
    if (seen.size() > most)
      return {};
  }
  return { seen.begin(), seen.end() };
}

std::string listed(const std::vector<long long>& values)
{
  std::ostringstream os;
  for (std::size_t i = 0; i < values.size(); ++i)
    os << (i == 0 ? "" : ", ") << values[i];
  return os.str();
}

/// A segment of a segmentation (3D Slicer's .seg.nrrd, a DICOM SEG): its
/// label value in its layer.
struct Segment
{
  int label = 0;
  std::string name;
  int layer = 0;
};

/// A segmentation's segments (the reader's field data); empty for any other
/// volume.
std::vector<Segment> segmentsOf(vtkImageData* image)
{
  std::vector<Segment> out;
  auto* names = vtkStringArray::SafeDownCast(image->GetFieldData()->GetAbstractArray("SegmentNames"));
  vtkDataArray* values = image->GetFieldData()->GetArray("SegmentLabelValues");
  vtkDataArray* layers = image->GetFieldData()->GetArray("SegmentLayers");
  if (!names || !values || names->GetNumberOfValues() != values->GetNumberOfTuples())
    return out;
  for (vtkIdType i = 0; i < names->GetNumberOfValues(); ++i)
  {
    Segment seg;
    seg.label = static_cast<int>(values->GetComponent(i, 0));
    seg.name = names->GetValue(i);
    if (layers && layers->GetNumberOfTuples() == names->GetNumberOfValues())
      seg.layer = static_cast<int>(layers->GetComponent(i, 0));
    out.push_back(seg);
  }
  return out;
}

/// "1 'mandible', 2 'maxilla'": the segments with their label values, and
/// their layers when there are several.
std::string segmentNames(const std::vector<Segment>& segments)
{
  const bool layered =
    std::any_of(segments.begin(), segments.end(), [](const Segment& seg) { return seg.layer != 0; });
  std::string text;
  for (std::size_t i = 0; i < segments.size(); ++i)
    text += (i == 0 ? "" : ", ") + std::to_string(segments[i].label) + " '" + segments[i].name + "'" +
      (layered ? " (layer " + std::to_string(segments[i].layer) + ")" : "");
  return text;
}

/// " (segments: 1 'mandible', 2 'maxilla')", or "" without segment names.
std::string segmentList(vtkImageData* image)
{
  const auto segments = segmentsOf(image);
  return segments.empty() ? std::string() : " (segments: " + segmentNames(segments) + ")";
}

/// For a volume of a few small whole numbers (a segmentation with several
/// labels, which is no 0/1 label map): how to take one of them.
std::string labelHint(vtkImageData* image, const double range[2])
{
  if (!(range[0] >= 0.0 && range[1] <= 255.0))
    return {};
  const std::vector<long long> values = fewIntegerValues(image->GetPointData()->GetScalars(), 16);
  if (values.size() < (segmentsOf(image).empty() ? 3u : 2u)) // a segmentation's one segment needs its label too
    return {};
  return " The volume holds only the values " + listed(values) + segmentList(image) +
    ": if it is a label map with several labels, Label (--label N) takes one of them.";
}

} // namespace

vtkLKBoneSurfaceFilter::vtkLKBoneSurfaceFilter() = default;

vtkLKBoneSurfaceFilter::~vtkLKBoneSurfaceFilter()
{
  this->SetPatientMatrix(nullptr);
  this->SetLabelName(nullptr);
}

void vtkLKBoneSurfaceFilter::SetPatientMatrix(vtkMatrix4x4* m)
{
  if (m == this->PatientMatrix)
  {
    return;
  }
  if (this->PatientMatrix)
  {
    this->PatientMatrix->UnRegister(this);
  }
  this->PatientMatrix = m;
  if (m)
  {
    m->Register(this);
  }
  this->Modified();
}

vtkMTimeType vtkLKBoneSurfaceFilter::GetMTime()
{
  vtkMTimeType t = this->Superclass::GetMTime();
  if (this->PatientMatrix)
  {
    t = std::max(t, this->PatientMatrix->GetMTime());
  }
  return t;
}

int vtkLKBoneSurfaceFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  return 1;
}

void vtkLKBoneSurfaceFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "IsoValue: " << this->IsoValue << "\n";
  os << indent << "ImageSmoothing: " << this->ImageSmoothing << "\n";
  os << indent << "SmoothingIterations: " << this->SmoothingIterations << "\n";
  os << indent << "LabelMapImageSmoothing: " << this->LabelMapImageSmoothing << "\n";
  os << indent << "LabelMapSmoothingIterations: " << this->LabelMapSmoothingIterations << "\n";
  os << indent << "FillCavities: " << this->FillCavities << "\n";
  os << indent << "ExtractionMode: " << this->ExtractionMode << "\n";
  os << indent << "SeedPoint: " << this->SeedPoint[0] << " " << this->SeedPoint[1] << " "
     << this->SeedPoint[2] << "\n";
  os << indent << "LabelMapMode: " << this->LabelMapMode << "\n";
  os << indent << "Label: " << this->Label << (this->Label > 0 ? "" : " (off)") << "\n";
  os << indent << "LabelName: " << (this->LabelName ? this->LabelName : "(none)") << "\n";
  os << indent << "Repair: " << this->Repair << "\n";
  os << indent << "Cropping: " << this->Cropping << "\n";
  os << indent << "CloseAtBorder: " << this->CloseAtBorder << "\n";
  os << indent << "CropBox: " << this->CropBox[0] << " " << this->CropBox[1] << " " << this->CropBox[2] << " "
     << this->CropBox[3] << " " << this->CropBox[4] << " " << this->CropBox[5] << "\n";
  os << indent << "PatientMatrix: ";
  if (this->PatientMatrix)
  {
    os << "\n";
    this->PatientMatrix->PrintSelf(os, indent.GetNextIndent());
  }
  else
  {
    os << "(none: the input's PatientMatrix field data, or the identity)\n";
  }
}

int vtkLKBoneSurfaceFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  this->EffectiveLabel = 0;
  this->EffectiveSegmentName.clear();
  if (!input || input->GetNumberOfPoints() == 0 || !input->GetPointData()->GetScalars())
  {
    vtkErrorMacro("The input volume is empty.");
    return 0;
  }
  int dims[3];
  input->GetDimensions(dims);
  if (dims[0] < 2 || dims[1] < 2 || dims[2] < 2)
  {
    vtkErrorMacro("The input volume must have at least 2 voxels along each axis, not "
      << dims[0] << " x " << dims[1] << " x " << dims[2] << ".");
    return 0;
  }
  const int components = input->GetNumberOfScalarComponents();
  const auto segments = segmentsOf(input);
  const bool layered = components > 1 && !segments.empty() &&
    std::all_of(segments.begin(), segments.end(), [&](const Segment& seg) { return seg.layer < components; });
  if (components != 1 && !layered)
  {
    vtkErrorMacro("The input volume must have one scalar component.");
    return 0;
  }
  if (!std::isfinite(this->IsoValue))
  {
    vtkErrorMacro("IsoValue must be a finite number.");
    return 0;
  }
  if (this->ExtractionMode == SEEDED_COMPONENT &&
    !(std::isfinite(this->SeedPoint[0]) && std::isfinite(this->SeedPoint[1]) && std::isfinite(this->SeedPoint[2])))
  {
    vtkErrorMacro("The SeedPoint (" << this->SeedPoint[0] << ", " << this->SeedPoint[1] << ", " << this->SeedPoint[2]
                                    << ") must be finite.");
    return 0;
  }
  if (!(this->ImageSmoothing <= 20.0)) // NaN too; an infinite one crashed vtkImageGaussianSmooth
  {
    vtkErrorMacro("ImageSmoothing must be a standard deviation from 0 to 20 voxels (negative: automatic), not "
      << this->ImageSmoothing << ".");
    return 0;
  }
  if (!(this->LabelMapImageSmoothing >= 0.0 && this->LabelMapImageSmoothing <= 20.0))
  {
    vtkErrorMacro("LabelMapImageSmoothing must be a standard deviation from 0 to 20 voxels, not "
      << this->LabelMapImageSmoothing << ".");
    return 0;
  }
  {
    // A zero or NaN spacing (a hand-made image, a header without spacing)
    // folds the volume flat: the contour would be a heap of degenerate faces.
    const double* sp = input->GetSpacing();
    const double* o = input->GetOrigin();
    const double det = input->GetDirectionMatrix()->Determinant();
    if (!(std::isfinite(sp[0]) && std::isfinite(sp[1]) && std::isfinite(sp[2])) || sp[0] == 0.0 ||
      sp[1] == 0.0 || sp[2] == 0.0 || !(std::isfinite(o[0]) && std::isfinite(o[1]) && std::isfinite(o[2])) ||
      !(std::isfinite(det) && std::abs(det) > 1e-12))
    {
      vtkErrorMacro("The input volume's geometry is invalid: spacing (" << sp[0] << ", " << sp[1] << ", " << sp[2]
                                                                       << ") must be finite and non-zero, origin ("
                                                                       << o[0] << ", " << o[1] << ", " << o[2]
                                                                       << ") finite, and the direction matrix "
                                                                       << "invertible.");
      return 0;
    }
  }

  // One label of several: a 0/1 label map of it (with the input's field
  // data, where the reader's patient matrix is). A layered segmentation's
  // segment is a label value in its layer's component.
  // The segment taken, by its name or by its label value (unique in a
  // single layer; in several, each layer of a 3D Slicer segmentation numbers
  // its segments from 1, while a DICOM SEG's numbers are its own, so a value
  // names a segment only when one segment has it).
  const Segment* chosen = nullptr;
  if (this->LabelName && *this->LabelName)
  {
    const std::string wanted = this->LabelName;
    auto lowered = [](std::string t) {
      std::transform(t.begin(), t.end(), t.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
      return t;
    };
    auto found = std::find_if(segments.begin(), segments.end(), [&](const Segment& seg) { return seg.name == wanted; });
    if (found == segments.end())
      found = std::find_if(
        segments.begin(), segments.end(), [&](const Segment& seg) { return lowered(seg.name) == lowered(wanted); });
    if (found == segments.end())
    {
      vtkErrorMacro("No segment is named '" << wanted << "'; "
                    << (segments.empty() ? std::string("the volume names no segments (a 3D Slicer .seg.nrrd, a DICOM SEG or an RT structure set does)")
                                         : "its segments are " + segmentNames(segments))
                    << ".");
      return 0;
    }
    chosen = &*found;
    // Two segments of one name (an RT structure set holding an organ twice,
    // as drawn and as edited): the first is taken, and the user told how to
    // take the other.
    std::string others;
    for (const Segment& seg : segments)
      if (&seg != chosen && lowered(seg.name) == lowered(chosen->name))
        others += (others.empty() ? "" : ", ") + std::to_string(seg.label) + " (layer " + std::to_string(seg.layer) + ")";
    if (!others.empty())
      vtkWarningMacro("More than one segment is named '" << wanted << "': the first, label " << chosen->label
                                                         << " (layer " << chosen->layer
                                                         << "), is taken; the others have the labels " << others
                                                         << " (Label, --label N takes one when no other has its value).");
  }
  else if (this->Label > 0 || layered)
  {
    std::vector<const Segment*> withLabel;
    for (const Segment& seg : segments)
      if (this->Label > 0 && seg.label == this->Label)
        withLabel.push_back(&seg);
    if (layered && withLabel.size() != 1)
    {
      const std::string label = std::to_string(this->Label);
      const std::string byName = "by its name (LabelName, --label NAME)";
      const std::string byEither = byName + " or by a label value only it has (Label, --label N)";
      vtkErrorMacro("The input is a segmentation whose segments overlap, in " << components << " layers; "
                    << (this->Label == 0 ? "choose one segment " + byEither
                          : withLabel.empty() ? "no segment has label " + label + "; choose one " + byEither
                                              : std::to_string(withLabel.size()) + " segments have label " + label +
                                                "; choose one " + byName)
                    << ". Its segments are " << segmentNames(segments) << ".");
      return 0;
    }
    if (!withLabel.empty())
      chosen = withLabel.front();
  }
  if (chosen && chosen->layer >= components) // field data that does not fit the volume (made by hand)
  {
    vtkErrorMacro("Segment '" << chosen->name << "' is in layer " << chosen->layer << ", but the volume has "
                              << components << " component" << (components == 1 ? "" : "s") << ".");
    return 0;
  }
  const int label = chosen ? chosen->label : this->Label;
  const int layer = chosen ? chosen->layer : 0;
  this->EffectiveLabel = label;
  if (chosen)
    this->EffectiveSegmentName = chosen->name;
  vtkNew<vtkImageData> oneLabel;
  if (label > 0)
  {
    vtkDataArray* s = input->GetPointData()->GetScalars();
    if (s->GetDataType() == VTK_FLOAT || s->GetDataType() == VTK_DOUBLE)
    {
      vtkErrorMacro("Label " << label << " needs a label map of integers; this volume holds "
                             << s->GetDataTypeAsString() << " values.");
      return 0;
    }
    oneLabel->CopyStructure(input);
    oneLabel->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
    oneLabel->GetFieldData()->ShallowCopy(input->GetFieldData());
    auto* out = static_cast<unsigned char*>(oneLabel->GetScalarPointer());
    const vtkIdType n = s->GetNumberOfTuples();
    vtkIdType hits = 0;
    for (vtkIdType i = 0; i < n; ++i)
    {
      out[i] = s->GetComponent(i, layer) == label;
      hits += out[i];
    }
    if (hits == 0)
    {
      const std::vector<long long> labels = fewIntegerValues(s, 64, layer);
      const std::string where = layered ? "layer " + std::to_string(layer) : std::string("the volume");
      vtkErrorMacro("No voxel holds label " << label << (layered ? " in " + where : std::string()) << "; "
                    << (labels.empty() ? where + " holds more than 64 values (is it a label map?)"
                                       : where + "'s values are " + listed(labels))
                    << segmentList(input) << ".");
      return 0;
    }
    input = oneLabel;
  }

  // Patient matrix: explicit, else the reader's field data, else identity.
  vtkNew<vtkMatrix4x4> matrix;
  vtkSmartPointer<vtkAbstractArray> space; // the reader's "SPACE" tag, passed on with its matrix
  if (this->PatientMatrix)
  {
    matrix->DeepCopy(this->PatientMatrix);
  }
  else if (vtkDataArray* m = input->GetFieldData()->GetArray("PatientMatrix"))
  {
    if (m->GetNumberOfTuples() * m->GetNumberOfComponents() == 16)
    {
      space = input->GetFieldData()->GetAbstractArray("SPACE");
      for (int i = 0; i < 16; ++i)
      {
        matrix->SetElement(i / 4, i % 4, m->GetComponent(i, 0));
      }
    }
  }

  // The crop (the box's voxels), or with CloseAtBorder the whole volume,
  // padded by one voxel of the volume's smallest value.
  vtkNew<vtkExtractVOI> voi;
  vtkNew<vtkImageConstantPad> pad;
  if (this->Cropping || this->CloseAtBorder)
  {
    int v[6];
    input->GetExtent(v);
    if (this->Cropping)
    {
      const std::string problem = cropExtent(input, matrix, this->CropBox, v);
      if (!problem.empty())
      {
        vtkErrorMacro("Cannot crop: " << problem << ".");
        return 0;
      }
      voi->SetInputData(input);
      voi->SetVOI(v);
      pad->SetInputConnection(voi->GetOutputPort());
    }
    else
      pad->SetInputData(input);
    double full[2];
    input->GetPointData()->GetScalars()->GetRange(full);
    pad->SetOutputWholeExtent(v[0] - 1, v[1] + 1, v[2] - 1, v[3] + 1, v[4] - 1, v[5] + 1);
    pad->SetConstant(full[0]);
    pad->Update();
    input = pad->GetOutput();
  }

  this->TreatedAsLabelMap = label > 0 || this->LabelMapMode == LABEL_MAP_ON ||
    (this->LabelMapMode == LABEL_MAP_AUTO && isBinaryLabelMap(input));
  this->EffectiveIsoValue = this->TreatedAsLabelMap ? 0.5 : this->IsoValue;
  double sigma = this->ImageSmoothing;
  if (sigma < 0.0)
  {
    sigma = this->TreatedAsLabelMap ? this->LabelMapImageSmoothing : 0.0;
  }
  const int iterations = this->SmoothingIterations >= 0 ? this->SmoothingIterations
    : this->TreatedAsLabelMap                           ? this->LabelMapSmoothingIterations
                                                        : 0;
  this->EffectiveImageSmoothing = sigma;
  this->EffectiveSmoothingIterations = iterations;

  double range[2];
  input->GetPointData()->GetScalars()->GetRange(range);
  if (!(this->EffectiveIsoValue > range[0] && this->EffectiveIsoValue < range[1]))
  {
    vtkErrorMacro("Iso value " << this->EffectiveIsoValue << " is outside the volume's range ["
                               << range[0] << ", " << range[1] << "]" << (this->Cropping ? " within the crop box" : "")
                               << ": no surface."
                               << (range[0] == range[1] && !this->Cropping
                                      ? std::string(" Every voxel holds the same value: the scan is blank, or its "
                                                    "pixel data could not be decoded (a damaged compressed file).")
                                      : labelHint(input, range)));
    return 0;
  }

  // A label map's content is often a small part of its grid (a mandible in
  // a whole CT's): the smoothing and the contour take the content's voxels
  // and a margin of background, twice the Gaussian's reach and two voxels
  // wide. No voxel's result changes: the Gaussian's kernel is renormalised
  // at the volume's edge, and near the margin's edge it meets background
  // only, as it did there before (3D Slicer crops a label map to its
  // content before its surface too). The TCIA mandible's 512 x 512 x 156
  // voxels become 119 x 117 x 38.
  vtkNew<vtkExtractVOI> content;
  if (this->TreatedAsLabelMap && input->GetNumberOfScalarComponents() == 1)
  {
    int whole[6], box[6];
    input->GetExtent(whole);
    if (contentExtent(input, range[0], box))
    {
      const int margin = 2 * static_cast<int>(std::ceil(3.0 * sigma)) + 2;
      vtkIdType kept = 1, all = 1;
      for (int a = 0; a < 3; ++a)
      {
        box[2 * a] = std::max(whole[2 * a], box[2 * a] - margin);
        box[2 * a + 1] = std::min(whole[2 * a + 1], box[2 * a + 1] + margin);
        kept *= box[2 * a + 1] - box[2 * a] + 1;
        all *= whole[2 * a + 1] - whole[2 * a] + 1;
      }
      if (kept < all)
      {
        content->SetInputData(input);
        content->SetVOI(box);
        content->Update();
        input = content->GetOutput();
      }
    }
  }

  vtkNew<vtkImageData> volume;
  volume->ShallowCopy(input);
  vtkSmartPointer<vtkImageData> smoothed = volume.GetPointer();
  vtkNew<vtkImageGaussianSmooth> gauss;
  lkvtk::ProgressRelay gaussProgress(this, gauss, 0.0, 0.15);
  vtkNew<vtkImageCast> toFloat;
  if (sigma > 0.0)
  {
    // Smooth in floating point: an integer label map would be truncated back to 0/1.
    toFloat->SetInputData(volume);
    toFloat->SetOutputScalarTypeToFloat();
    gauss->SetInputConnection(toFloat->GetOutputPort());
    gauss->SetStandardDeviations(sigma, sigma, sigma);
    gauss->SetRadiusFactors(3.0, 3.0, 3.0);
    gauss->Update();
    smoothed = gauss->GetOutput();
  }
  if (lkvtk::stopRequested(this, { output }))
  {
    return 1;
  }

  if (this->FillCavities)
  {
    // Enclosed low voxels take the largest value: only the outer surface remains.
    vtkNew<vtkImageData> filled;
    filled->DeepCopy(smoothed);
    vtkDataArray* scalars = filled->GetPointData()->GetScalars();
    const vtkIdType n = scalars->GetNumberOfTuples();
    std::vector<char> enclosed;
    try
    {
      std::vector<char> low(static_cast<std::size_t>(n));
      for (vtkIdType v = 0; v < n; ++v)
        low[static_cast<std::size_t>(v)] = scalars->GetComponent(v, 0) < this->EffectiveIsoValue;
      int size[3]; // the volume's as cropped or padded, not the input's
      filled->GetDimensions(size);
      enclosed = lk::enclosedBackground(low, size[0], size[1], size[2], true);
    }
    catch (const std::exception& e) // out of memory for a huge volume's flags
    {
      vtkErrorMacro("Cannot fill the cavities: " << e.what());
      return 0;
    }
    const double top = scalars->GetRange(0)[1];
    for (vtkIdType v = 0; v < n; ++v)
      if (enclosed[static_cast<std::size_t>(v)])
        scalars->SetComponent(v, 0, top);
    scalars->Modified();
    smoothed = filled;
  }

  vtkNew<vtkFlyingEdges3D> contour;
  lkvtk::ProgressRelay contourProgress(this, contour, 0.15, 0.4);
  contour->SetInputData(smoothed);
  contour->SetValue(0, this->EffectiveIsoValue);
  contour->ComputeNormalsOff();
  contour->ComputeGradientsOff();
  contour->ComputeScalarsOff();
  contour->Update();
  if (contour->GetOutput()->GetNumberOfPolys() == 0)
  {
    // A label map's few or thin voxels that the Gaussian took below 0.5
    // (--label 1 on a CT: its scattered voxels of 1 HU) are said so.
    std::ostringstream why;
    if (this->TreatedAsLabelMap && sigma > 0.0)
    {
      const vtkIdType labelled = labelledVoxels(volume);
      why << " The label map's " << labelled << " labelled voxel" << (labelled == 1 ? " lies" : "s lie")
          << " too thin or too far apart: the Gaussian of " << sigma << " voxel (ImageSmoothing) leaves none at 0.5; "
          << "ImageSmoothing 0 (--image-smooth 0) keeps them";
      if (label > 0)
        why << " (is the input a label map? label " << label << " was taken from it)";
      why << ".";
    }
    vtkErrorMacro("No surface at iso value " << this->EffectiveIsoValue << "." << why.str());
    return 0;
  }
  if (lkvtk::stopRequested(this, { output }))
  {
    return 1;
  }

  // A label map's smoothing thins what is only a few voxels thick (a
  // printed guide's wall, read back from a structure set): said when the
  // surface encloses much less than the labelled voxels do.
  if (this->TreatedAsLabelMap && sigma > 0.0 && !this->FillCavities)
  {
    const vtkIdType labelled = labelledVoxels(volume);
    const double* h = volume->GetSpacing();
    const double voxels = static_cast<double>(labelled) * std::abs(h[0] * h[1] * h[2]);
    const bool closed = lkvtk::countOpenEdges(contour->GetOutput()) == 0;
    vtkNew<vtkMassProperties> enclosed;
    enclosed->SetInputConnection(contour->GetOutputPort());
    enclosed->Update();
    if (closed && voxels > 0.0 && enclosed->GetVolume() < 0.8 * voxels)
      vtkWarningMacro("The label map's smoothing (a Gaussian of " << sigma << " voxel) left "
        << std::lround(100.0 * enclosed->GetVolume() / voxels) << " % of the labelled voxels' volume inside the "
        << "surface: a structure a few voxels thin (a guide's wall) is eaten away; ImageSmoothing 0 "
        << "(--image-smooth 0) keeps it.");
  }

  // Component selection in data coordinates.
  vtkSmartPointer<vtkPolyData> surface = contour->GetOutput();
  vtkNew<vtkPolyDataConnectivityFilter> connectivity;
  lkvtk::ProgressRelay connectivityProgress(this, connectivity, 0.4, 0.5);
  if (this->ExtractionMode != ALL_COMPONENTS)
  {
    connectivity->SetInputData(surface);
    if (this->ExtractionMode == LARGEST_COMPONENT)
    {
      connectivity->SetExtractionModeToLargestRegion();
    }
    else
    {
      vtkNew<vtkMatrix4x4> inverse;
      vtkMatrix4x4::Invert(matrix, inverse);
      double seed[4] = { this->SeedPoint[0], this->SeedPoint[1], this->SeedPoint[2], 1.0 };
      double local[4];
      inverse->MultiplyPoint(seed, local);
      connectivity->SetExtractionModeToClosestPointRegion();
      connectivity->SetClosestPoint(local);
    }
    connectivity->ScalarConnectivityOff();
    connectivity->Update();
    surface = connectivity->GetOutput();
  }
  if (lkvtk::stopRequested(this, { output }))
  {
    return 1;
  }

  // Into patient space.
  vtkNew<vtkTransform> transform;
  transform->SetMatrix(matrix);
  vtkNew<vtkTransformPolyDataFilter> place;
  place->SetInputData(surface);
  place->SetTransform(transform);
  place->SetOutputPointsPrecision(vtkAlgorithm::DOUBLE_PRECISION);
  place->Update();
  surface = place->GetOutput();
  if (matrix->Determinant() < 0.0)
  {
    vtkNew<vtkReverseSense> reverse;
    reverse->SetInputData(surface);
    reverse->ReverseCellsOn();
    reverse->ReverseNormalsOff();
    reverse->Update();
    surface = reverse->GetOutput();
  }
  this->UpdateProgress(0.55);

  vtkNew<vtkLKMeshRepairFilter> repair;
  lkvtk::ProgressRelay repairProgress(this, repair, 0.55, 0.85);
  if (this->Repair)
  {
    repair->SetInputData(surface);
    repair->Update();
    if (repair->GetOutput()->GetNumberOfPolys() == 0)
    {
      vtkErrorMacro("The repair left no triangles.");
      return 0;
    }
    surface = repair->GetOutput();
  }
  if (lkvtk::stopRequested(this, { output }))
  {
    return 1;
  }

  vtkNew<vtkWindowedSincPolyDataFilter> smoother;
  lkvtk::ProgressRelay smoothProgress(this, smoother, 0.85, 1.0);
  if (iterations > 0)
  {
    smoother->SetInputData(surface);
    smoother->SetNumberOfIterations(iterations);
    smoother->SetPassBand(0.1);
    smoother->BoundarySmoothingOff();
    smoother->FeatureEdgeSmoothingOff();
    smoother->NonManifoldSmoothingOn();
    smoother->NormalizeCoordinatesOn();
    smoother->Update();
    surface = smoother->GetOutput();
  }
  if (lkvtk::stopRequested(this, { output }))
  {
    return 1;
  }
  output->ShallowCopy(surface);
  output->GetPointData()->Initialize();
  // The output's own field data (the repair's counts, and what the volume
  // carried), not the last filter's. The volume's PatientMatrix is applied
  // and does not describe the surface; its SPACE tag holds only with that
  // matrix (a matrix given with SetPatientMatrix brings none).
  vtkNew<vtkFieldData> fields;
  fields->DeepCopy(surface->GetFieldData());
  fields->RemoveArray("PatientMatrix");
  fields->RemoveArray("SPACE");
  if (space)
    fields->AddArray(space);
  output->SetFieldData(fields);
  this->UpdateProgress(1.0);
  return 1;
}
