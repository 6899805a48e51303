/// \file vtkLKDICOMStructureSet.cxx
/// Private: a DICOM RT structure set (RTSTRUCT) read into a label volume.
/// Radiotherapy planning systems store the organs they contour (the
/// mandible is an organ at risk of every head and neck plan) as stacks of
/// closed polygons in patient coordinates, one per slice, without pixels.
/// Each ROI's polygons are filled slice by slice by VTK's
/// vtkPolyDataToImageStencil (even-odd: a polygon inside another is a hole)
/// on a grid in the polygons' planes; ROIs that overlap (the body and the
/// organs in it) go to layers of their own.

#include "vtkLKDICOMSeries.h"

#include <vtkAlgorithm.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkDICOMDirectory.h>
#include <vtkDICOMItem.h>
#include <vtkDICOMMetaData.h>
#include <vtkDICOMSequence.h>
#include <vtkDICOMValue.h>
#include <vtkImageData.h>
#include <vtkImageEuclideanDistance.h>
#include <vtkImageStencilData.h>
#include <vtkMatrix4x4.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataToImageStencil.h>
#include <vtkStringArray.h>
#include <vtksys/SystemTools.hxx>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace lkvtk
{

namespace
{

/// Two contour planes closer than this (mm) are one: ContourData is stored
/// as decimal strings, rounded far below it, and no scan has slices this close.
constexpr double kPlaneTolerance = 0.05;

/// A contour point farther than this (mm) from the patient origin is damage,
/// not anatomy (10 m).
constexpr double kFarthest = 1.0e4;

/// Empty slices and pixels around the contours, so that the surface closes.
constexpr int kPad = 2;

struct Contour
{
  std::vector<V3> points; // patient (LPS) mm
  double w = 0.0;         // along the frame's normal
  int slice = 0;
};

struct ROI
{
  int number = 0;
  std::string name;
  std::vector<Contour> contours; // closed planar ones
  std::set<std::string> otherTypes;
};

/// How many items a sequence holds: 0 for a value that is not a sequence
/// (a damaged file's), whose items are not there to read.
unsigned int itemCount(const vtkDICOMValue& sequence)
{
  return sequence.GetSequenceData() ? sequence.GetNumberOfValues() : 0;
}

std::string mm(double v)
{
  std::ostringstream os;
  os << v << " mm";
  return os.str();
}

/// The numbers of a decimal string value (DS: "1.5\\-2\\+3e1"), each read
/// as written: vtkDICOMValue reads what is not a number ("nan", "1,5",
/// "") as 0, which would put a contour's point at the patient origin.
bool decimals(const std::string& text, std::vector<double>& out)
{
  out.clear();
  std::size_t start = 0;
  while (start <= text.size())
  {
    std::size_t end = text.find('\\', start);
    if (end == std::string::npos)
      end = text.size();
    std::size_t a = start, b = end;
    while (a < b && text[a] == ' ')
      ++a;
    while (b > a && text[b - 1] == ' ')
      --b;
    if (a < b && text[a] == '+')
      ++a;
    double v = 0.0;
    const auto [ptr, ec] = std::from_chars(text.data() + a, text.data() + b, v);
    if (a == b || ec != std::errc() || ptr != text.data() + b || !std::isfinite(v))
      return false;
    out.push_back(v);
    start = end + 1;
  }
  return true;
}

/// The ROIs of the structure set, each with its closed planar contours.
bool readROIs(vtkDICOMMetaData* meta, std::vector<ROI>& rois, int& skippedShort, std::string& error)
{
  std::map<int, std::size_t> byNumber;
  const vtkDICOMValue& list = meta->Get(DC::StructureSetROISequence);
  for (unsigned int i = 0; i < itemCount(list); ++i)
  {
    const vtkDICOMItem& item = list.GetSequenceData()[i];
    ROI roi;
    roi.number = item.Get(DC::ROINumber).AsInt();
    roi.name = dicomText(item.Get(DC::ROIName));
    if (roi.name.empty())
      roi.name = "ROI " + std::to_string(roi.number);
    if (byNumber.count(roi.number))
    {
      error = "two ROIs of the RT structure set have the ROINumber " + std::to_string(roi.number);
      return false;
    }
    byNumber[roi.number] = rois.size();
    rois.push_back(roi);
  }
  if (rois.empty())
  {
    error = "the RT structure set lists no ROIs (StructureSetROISequence)";
    return false;
  }
  const vtkDICOMValue& contoured = meta->Get(DC::ROIContourSequence);
  for (unsigned int i = 0; i < itemCount(contoured); ++i)
  {
    const vtkDICOMItem& item = contoured.GetSequenceData()[i];
    const int number = item.Get(DC::ReferencedROINumber).AsInt();
    const auto found = byNumber.find(number);
    if (found == byNumber.end())
    {
      error = "the RT structure set has contours of ROI " + std::to_string(number) +
        ", which its StructureSetROISequence does not list";
      return false;
    }
    ROI& roi = rois[found->second];
    const vtkDICOMValue& contours = item.Get(DC::ContourSequence);
    for (unsigned int c = 0; c < itemCount(contours); ++c)
    {
      const vtkDICOMItem& contour = contours.GetSequenceData()[c];
      const std::string type = contour.Get(DC::ContourGeometricType).AsString();
      if (type != "CLOSED_PLANAR" && type != "CLOSEDPLANAR_XOR")
      {
        roi.otherTypes.insert(type.empty() ? std::string("no type") : type);
        continue;
      }
      const vtkDICOMValue& data = contour.Get(DC::ContourData);
      const unsigned int values = data.GetNumberOfValues();
      const vtkDICOMValue& count = contour.Get(DC::NumberOfContourPoints);
      if (values % 3 != 0 || (count.IsValid() && static_cast<unsigned int>(count.AsInt()) * 3 != values))
      {
        error = "a contour of ROI '" + roi.name + "' has " + std::to_string(values) +
          " ContourData values, which is not three per point" +
          (count.IsValid() ? " of its NumberOfContourPoints (" + std::to_string(count.AsInt()) + ")" : "");
        return false;
      }
      if (values < 9)
      {
        ++skippedShort; // a point or a segment encloses nothing
        continue;
      }
      std::vector<double> xyz;
      if (!decimals(data.AsString(), xyz) || xyz.size() != values)
      {
        error = "a contour of ROI '" + roi.name + "' has a coordinate that is not a number";
        return false;
      }
      const auto far = std::find_if(xyz.begin(), xyz.end(), [](double v) { return std::abs(v) > kFarthest; });
      if (far != xyz.end())
      {
        std::ostringstream os;
        os << "a contour of ROI '" << roi.name << "' has a point at " << *far
           << " mm: no patient reaches that far from the scanner's origin";
        error = os.str();
        return false;
      }
      Contour one;
      for (unsigned int p = 0; p < values; p += 3)
        one.points.push_back({ xyz[p], xyz[p + 1], xyz[p + 2] });
      roi.contours.push_back(std::move(one));
    }
  }
  return true;
}

/// The signed distance of each pixel of a slice's mask to its outline, in
/// pixels (VTK's Euclidean distance transform, from either side): negative
/// inside, the outline half-way between the pixels inside and outside. Its
/// blend between two contoured slices is the shape-based interpolation of
/// the slices between (Raya and Udupa): a shape that grows, shrinks or moves
/// does so gradually, and shapes that do not overlap are not joined.
std::vector<float> signedDistance(const unsigned char* mask, int nx, int ny)
{
  const vtkIdType n = static_cast<vtkIdType>(nx) * ny;
  std::vector<float> distance(static_cast<std::size_t>(n), 0.0f);
  for (const bool inside : { true, false })
  {
    vtkNew<vtkImageData> image;
    image->SetDimensions(nx, ny, 1);
    image->AllocateScalars(VTK_FLOAT, 1);
    float* v = static_cast<float*>(image->GetScalarPointer());
    for (vtkIdType p = 0; p < n; ++p)
      v[p] = (mask[p] != 0) == inside ? 1.0f : 0.0f; // the distance of each pixel of 1s to the nearest 0
    vtkNew<vtkImageEuclideanDistance> transform;
    transform->SetInputData(image);
    transform->SetDimensionality(2);
    transform->ConsiderAnisotropyOff();
    transform->Update();
    vtkDataArray* squared = transform->GetOutput()->GetPointData()->GetScalars();
    for (vtkIdType p = 0; p < n; ++p)
      if ((mask[p] != 0) == inside)
      {
        const float d = static_cast<float>(std::sqrt(squared->GetComponent(p, 0))) - 0.5f;
        distance[static_cast<std::size_t>(p)] = inside ? -d : d;
      }
  }
  return distance;
}

/// The normal of a polygon (Newell), as long as twice its area.
V3 areaNormal(const std::vector<V3>& points)
{
  V3 n{ 0.0, 0.0, 0.0 };
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const V3& a = points[i];
    const V3& b = points[(i + 1) % points.size()];
    n[0] += (a[1] - b[1]) * (a[2] + b[2]);
    n[1] += (a[2] - b[2]) * (a[0] + b[0]);
    n[2] += (a[0] - b[0]) * (a[1] + b[1]);
  }
  return n;
}

/// A frame whose normal is that of the largest contour (made to point along
/// the positive side of its main axis), its rows along the patient axis most
/// across it: axial contours get the frame of an axial CT.
bool contourFrame(const std::vector<ROI>& rois, SliceFrame& frame)
{
  V3 best{ 0.0, 0.0, 0.0 };
  for (const ROI& roi : rois)
    for (const Contour& c : roi.contours)
    {
      const V3 n = areaNormal(c.points);
      if (dot(n, n) > dot(best, best))
        best = n;
    }
  const double length = std::sqrt(dot(best, best));
  if (!(length > 1e-9))
    return false;
  V3 n{ best[0] / length, best[1] / length, best[2] / length };
  const std::size_t main = static_cast<std::size_t>(
    std::max_element(n.begin(), n.end(), [](double a, double b) { return std::abs(a) < std::abs(b); }) - n.begin());
  if (n[main] < 0.0)
    n = { -n[0], -n[1], -n[2] };
  const std::size_t across = static_cast<std::size_t>(
    std::min_element(n.begin(), n.end(), [](double a, double b) { return std::abs(a) < std::abs(b); }) - n.begin());
  V3 r{ 0.0, 0.0, 0.0 };
  r[across] = 1.0;
  const double along = dot(r, n);
  for (std::size_t a = 0; a < 3; ++a)
    r[a] -= along * n[a];
  const double rl = std::sqrt(dot(r, r));
  for (double& v : r)
    v /= rl;
  frame = { r, cross(n, r), n };
  return true;
}

/// Whether every contour lies in a plane of the frame; sets each one's w.
bool planarIn(const SliceFrame& frame, std::vector<ROI>& rois)
{
  for (ROI& roi : rois)
    for (Contour& c : roi.contours)
    {
      double lo = std::numeric_limits<double>::max(), hi = std::numeric_limits<double>::lowest();
      for (const V3& p : c.points)
      {
        const double w = dot(frame.n, p);
        lo = std::min(lo, w);
        hi = std::max(hi, w);
      }
      if (hi - lo > kPlaneTolerance)
        return false;
      c.w = 0.5 * (lo + hi);
    }
  return true;
}

/// The SeriesInstanceUIDs of the image series the structure set references
/// (its RT referenced series), or a DICOM SEG references (its
/// ReferencedSeriesSequence).
std::vector<std::string> referencedSeriesUIDs(vtkDICOMMetaData* meta)
{
  std::vector<std::string> uids;
  const vtkDICOMValue& segSeries = meta->Get(DC::ReferencedSeriesSequence);
  for (unsigned int i = 0; i < itemCount(segSeries); ++i)
  {
    const std::string uid = segSeries.GetSequenceData()[i].Get(DC::SeriesInstanceUID).AsString();
    if (!uid.empty())
      uids.push_back(uid);
  }
  const vtkDICOMValue& frames = meta->Get(DC::ReferencedFrameOfReferenceSequence);
  for (unsigned int f = 0; f < itemCount(frames); ++f)
  {
    const vtkDICOMValue& studies = frames.GetSequenceData()[f].Get(DC::RTReferencedStudySequence);
    for (unsigned int s = 0; s < itemCount(studies); ++s)
    {
      const vtkDICOMValue& series = studies.GetSequenceData()[s].Get(DC::RTReferencedSeriesSequence);
      for (unsigned int i = 0; i < itemCount(series); ++i)
      {
        const std::string uid = series.GetSequenceData()[i].Get(DC::SeriesInstanceUID).AsString();
        if (!uid.empty())
          uids.push_back(uid);
      }
    }
  }
  return uids;
}

/// The image series the structure set references, or none.
const DICOMSeriesInfo* referencedImages(vtkDICOMMetaData* meta, const std::vector<DICOMSeriesInfo>& imageSeries)
{
  for (const std::string& uid : referencedSeriesUIDs(meta))
    for (const DICOMSeriesInfo& one : imageSeries)
      if (one.uid == uid && !one.files.empty() && one.sopClass != kSegmentationStorage)
        return &one;
  return nullptr;
}

/// The studies and frames of reference a DICOM object belongs to: its own
/// StudyInstanceUID and FrameOfReferenceUID, and those an RT structure set
/// names in its ReferencedFrameOfReferenceSequence.
struct StudyKeys
{
  std::vector<std::string> studies, frames;

  explicit StudyKeys(vtkDICOMMetaData* meta)
  {
    add(studies, meta->Get(DC::StudyInstanceUID).AsString());
    add(frames, meta->Get(DC::FrameOfReferenceUID).AsString());
    const vtkDICOMValue& referenced = meta->Get(DC::ReferencedFrameOfReferenceSequence);
    for (unsigned int f = 0; f < itemCount(referenced); ++f)
    {
      const vtkDICOMItem& frame = referenced.GetSequenceData()[f];
      add(frames, frame.Get(DC::FrameOfReferenceUID).AsString());
      const vtkDICOMValue& study = frame.Get(DC::RTReferencedStudySequence);
      for (unsigned int s = 0; s < itemCount(study); ++s)
        add(studies, study.GetSequenceData()[s].Get(DC::ReferencedSOPInstanceUID).AsString());
    }
  }

  /// Whether the folder's first DICOM file is of one of these studies or
  /// frames of reference.
  bool share(const FolderBeside& folder) const
  {
    return has(studies, folder.studyUID) || has(frames, folder.frameUID);
  }

private:
  static bool has(const std::vector<std::string>& uids, const std::string& uid)
  {
    return !uid.empty() && std::find(uids.begin(), uids.end(), uid) != uids.end();
  }
  static void add(std::vector<std::string>& uids, const std::string& uid)
  {
    if (!uid.empty() && !has(uids, uid))
      uids.push_back(uid);
  }
};

/// The image series `meta` (read from `file`) references: among
/// `imageSeries` (the series of its own folder), else in a folder beside
/// its folder (a study exported one series to a folder), copied into
/// `beside`: first those whose first file is of that series, then those of
/// the object's study or frame of reference (a folder that holds several
/// series). Null when it is in neither; `crowded` (when given) then says
/// whether the folders beside were too many to search.
const DICOMSeriesInfo* referencedImagesNear(vtkDICOMMetaData* meta, const std::string& file,
  const std::vector<DICOMSeriesInfo>& imageSeries, DICOMSeriesInfo& beside, bool* crowded = nullptr)
{
  if (crowded)
    *crowded = false;
  if (const DICOMSeriesInfo* images = referencedImages(meta, imageSeries))
    return images;
  const std::vector<std::string> uids = referencedSeriesUIDs(meta);
  if (uids.empty())
    return nullptr;
  const std::vector<FolderBeside> folders = foldersBeside(vtksys::SystemTools::GetFilenamePath(file), crowded);
  const StudyKeys keys(meta);
  for (const bool firstFileOfTheSeries : { true, false })
    for (const FolderBeside& folder : folders)
    {
      const bool ofTheSeries = std::find(uids.begin(), uids.end(), folder.seriesUID) != uids.end();
      if (firstFileOfTheSeries ? !ofTheSeries : (ofTheSeries || !keys.share(folder)))
        continue;
      std::vector<DICOMSeriesInfo> series;
      std::string ignored;
      if (!findDICOMSeries(folder.folder, series, ignored, nullptr, 1))
        continue;
      if (const DICOMSeriesInfo* images = referencedImages(meta, series))
      {
        beside = *images;
        return &beside;
      }
    }
  return nullptr;
}

/// Where the slices of an image series lie along `normal` (sorted, one per
/// position); empty when an image has no position.
std::vector<double> slicePlanes(const DICOMSeriesInfo& series, const V3& normal)
{
  std::vector<ImagePosition> images;
  std::string ignored;
  if (!readImagePositions(series, images, ignored))
    return {};
  std::vector<double> planes;
  for (const ImagePosition& image : images)
    planes.push_back(dot(normal, image.position));
  std::sort(planes.begin(), planes.end());
  planes.erase(std::unique(planes.begin(), planes.end(), [](double a, double b) { return b - a < kPlaneTolerance; }),
    planes.end());
  return planes;
}

/// Where the voxels lie: the frame, the pixel lattice (through `lattice`,
/// `dx` by `dy` mm), the slices (`h` mm apart from `z0` along the normal)
/// and the grid's corner (`first`, in the frame from the lattice point).
struct Grid
{
  SliceFrame frame;
  V3 lattice{ 0.0, 0.0, 0.0 };
  double dx = 1.0, dy = 1.0, h = 1.0, z0 = 0.0;
  double first[2] = { 0.0, 0.0 };
  int dims[3] = { 0, 0, 0 };
};

/// The grid of the structure set's voxels (see readDICOMStructureSet), and
/// each contour's slice on it.
bool placeGrid(vtkDICOMMetaData* meta, const DICOMSeriesInfo* images, bool crowded, std::vector<ROI>& rois,
  Grid& grid, std::vector<std::string>& notes, std::string& error)
{
  // The frame and the pixel lattice: the referenced CT's (`images`, when it
  // was found near the structure set) when its slices are parallel to the
  // contours.
  SliceFrame frame;
  double dx = 0.0, dy = 0.0;
  V3 lattice{ 0.0, 0.0, 0.0 }; // a pixel centre of the CT (or the patient origin)
  bool fromImages = false;
  const std::string imageFile = images ? images->files.front() : std::string();
  if (images)
  {
    vtkNew<vtkDICOMMetaData> image;
    std::string ignored;
    double iop[6], ps[2], ipp[3];
    const bool known = readDICOMHeader(imageFile, image, ignored) &&
      image->Get(DC::ImageOrientationPatient).GetNumberOfValues() >= 6 &&
      image->Get(DC::PixelSpacing).GetNumberOfValues() >= 2 &&
      image->Get(DC::ImagePositionPatient).GetNumberOfValues() >= 3;
    if (known)
    {
      image->Get(DC::ImageOrientationPatient).GetValues(iop, 6);
      image->Get(DC::PixelSpacing).GetValues(ps, 2);
      image->Get(DC::ImagePositionPatient).GetValues(ipp, 3);
      if (sliceFrame(iop, frame) && ps[0] > 0.0 && ps[1] > 0.0 && std::isfinite(ipp[0] + ipp[1] + ipp[2]) &&
        planarIn(frame, rois))
      {
        fromImages = true;
        dx = ps[1]; // PixelSpacing is (row spacing, column spacing)
        dy = ps[0];
        lattice = { ipp[0], ipp[1], ipp[2] };
      }
    }
  }
  if (!fromImages)
  {
    if (!contourFrame(rois, frame))
    {
      error = "the contours of the RT structure set enclose no area";
      return false;
    }
    if (!planarIn(frame, rois))
    {
      error = "the contours of the RT structure set do not lie in parallel planes";
      return false;
    }
  }

  // The contours' extent in the frame, from the pixel lattice's point.
  double lo[2] = { std::numeric_limits<double>::max(), std::numeric_limits<double>::max() };
  double hi[2] = { std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest() };
  for (const ROI& roi : rois)
    for (const Contour& c : roi.contours)
      for (const V3& p : c.points)
      {
        const V3 d = sub(p, lattice);
        lo[0] = std::min(lo[0], dot(frame.r, d));
        hi[0] = std::max(hi[0], dot(frame.r, d));
        lo[1] = std::min(lo[1], dot(frame.c, d));
        hi[1] = std::max(hi[1], dot(frame.c, d));
      }

  // The slices: the contours' planes, spaced by the smallest gap.
  std::vector<double> planes;
  for (const ROI& roi : rois)
    for (const Contour& c : roi.contours)
      planes.push_back(c.w);
  std::sort(planes.begin(), planes.end());
  std::vector<double> distinct{ planes.front() };
  for (double w : planes)
    if (w - distinct.back() > kPlaneTolerance)
      distinct.push_back(w);
  double h = 0.0;
  for (std::size_t k = 1; k < distinct.size(); ++k)
    h = h == 0.0 ? distinct[k] - distinct[k - 1] : std::min(h, distinct[k] - distinct[k - 1]);
  if (!fromImages)
  {
    // 1 mm pixels, or finer where the contours are: the slice spacing, or
    // the contours' own point spacing (their median segment, about the
    // pixel of the CT they were drawn on), down to 0.5 mm, while the volume
    // stays within 1e8 voxels (1e9 over its ROIs). A 0.5 mm CT's thin bone
    // (the orbits' walls) is lost to 1 mm pixels; 0.25 mm would cost four
    // times the time and memory for little (NOTES, session 46).
    dx = h > 0.0 ? std::min(1.0, h) : 1.0;
    std::vector<double> segments;
    for (const ROI& roi : rois)
      for (const Contour& c : roi.contours)
        for (std::size_t i = 0; i < c.points.size(); ++i)
        {
          const V3 d = sub(c.points[(i + 1) % c.points.size()], c.points[i]);
          segments.push_back(std::sqrt(dot(d, d)));
        }
    if (!segments.empty())
    {
      std::nth_element(segments.begin(), segments.begin() + segments.size() / 2, segments.end());
      const double spacing = std::max(0.5, segments[segments.size() / 2]);
      const double slices = h > 0.0 ? (distinct.back() - distinct.front()) / h + 1.0 : 1.0;
      const double area = (hi[0] - lo[0] + 2.0) * (hi[1] - lo[1] + 2.0);
      // Overlapping ROIs take a layer each: a radiotherapy set of 30 ROIs
      // (a body, targets over organs) stays on 1 mm pixels.
      const double layers = static_cast<double>(std::max<std::size_t>(1, rois.size()));
      while (spacing < dx)
      {
        const double finer = std::max(spacing, 0.5 * dx);
        const double voxels = area / (finer * finer) * slices;
        if (voxels > 1.0e8 || voxels * layers > 1.0e9)
          break;
        dx = finer;
      }
    }
    dy = dx;
    const std::vector<std::string> uids = referencedSeriesUIDs(meta);
    const std::string uid = uids.empty() ? std::string() : uids.front();
    notes.push_back(std::string("the image series the structure set was drawn on") +
      (uid.empty() ? std::string("") : " (" + uid + ")") +
      (!imageFile.empty() ? " lies across its contours"
          : crowded ? " is not in its folder, and the folders beside it were not searched (over " +
              std::to_string(kFoldersBesideLimit) + " of them: not a study's)"
                    : " is neither in its folder nor in a folder beside it") +
      ": its ROIs are filled on a grid of their own, " + mm(dx) + " pixels" +
      (h > 0.0 ? " and " + mm(h) + " slices" : std::string("")));
  }
  if (h == 0.0)
    h = std::min(dx, dy); // one plane: a slab a pixel thick
  // On the CT's slices, when the contours lie on them and they are evenly
  // spaced: an ROI contoured on every other slice is then interpolated at
  // the CT's resolution, not filled on a grid of twice its spacing.
  double zBase = distinct.front();
  if (fromImages)
  {
    const std::vector<double> ct = slicePlanes(*images, frame.n);
    double gap = 0.0;
    for (std::size_t k = 1; k < ct.size(); ++k)
      gap = k == 1 ? ct[k] - ct[k - 1] : std::min(gap, ct[k] - ct[k - 1]);
    auto onLattice = [&](double w) {
      const double at = (w - ct.front()) / gap;
      return std::abs(at - std::round(at)) * gap < kPlaneTolerance;
    };
    if (gap > 0.0 && gap < h + kPlaneTolerance && std::all_of(ct.begin(), ct.end(), onLattice) &&
      std::all_of(distinct.begin(), distinct.end(), onLattice))
    {
      h = gap;
      zBase = ct.front();
    }
  }
  if (!((distinct.back() - distinct.front()) / h < 1.0e5))
  {
    error = "the contours of the RT structure set span " + mm(distinct.back() - distinct.front()) +
      " across their planes, too many slices of " + mm(h);
    return false;
  }
  const double z0 = zBase + (std::round((distinct.front() - zBase) / h) - kPad) * h;
  double moved = 0.0;
  int sliceCount = 0;
  for (ROI& roi : rois)
    for (Contour& c : roi.contours)
    {
      const double at = (c.w - z0) / h;
      c.slice = static_cast<int>(std::lround(at));
      moved = std::max(moved, std::abs(at - c.slice) * h);
      sliceCount = std::max(sliceCount, c.slice + 1 + kPad);
    }
  if (moved > kPlaneTolerance)
    notes.push_back("the contours' planes are not evenly spaced: some were moved up to " + mm(moved) +
      " onto the slices of " + mm(h));

  // The pixels: the contours' extent in the frame (above), on the CT's pixel lattice.
  const double first[2] = { (std::floor(lo[0] / dx) - kPad) * dx, (std::floor(lo[1] / dy) - kPad) * dy };
  const double nxd = std::ceil((hi[0] - first[0]) / dx) + kPad + 1, nyd = std::ceil((hi[1] - first[1]) / dy) + kPad + 1;
  if (!(nxd * nyd * sliceCount <= 1.0e9))
  {
    error = "the contours of the RT structure set span " + mm(hi[0] - lo[0]) + " by " + mm(hi[1] - lo[1]) + " by " +
      mm(distinct.back() - distinct.front()) + ": too large a volume at " + mm(dx) + " pixels and " + mm(h) + " slices";
    return false;
  }
  grid.dims[0] = static_cast<int>(nxd);
  grid.dims[1] = static_cast<int>(nyd);
  grid.dims[2] = sliceCount;
  grid.frame = frame;
  grid.lattice = lattice;
  grid.dx = dx;
  grid.dy = dy;
  grid.h = h;
  grid.z0 = z0;
  grid.first[0] = first[0];
  grid.first[1] = first[1];
  return true;
}

/// The voxels of one ROI, from its first slice (`zFirst`) to its last: its
/// contours filled by VTK (vtkPolyDataToImageStencil, even-odd), the slices
/// it skips interpolated from the contours on either side (gaps of up to
/// twice its usual contour spacing; wider ones are left empty, and noted).
std::vector<unsigned char> fillROI(const ROI& roi, const Grid& grid, int& zFirst, std::vector<std::string>& notes)
{
  const int* dims = grid.dims;
  const vtkIdType sliceSize = static_cast<vtkIdType>(dims[0]) * dims[1];
  const SliceFrame& frame = grid.frame;
  const double h = grid.h;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  std::set<int> slices;
  for (const Contour& c : roi.contours)
  {
    slices.insert(c.slice);
    lines->InsertNextCell(static_cast<int>(c.points.size()) + 1);
    const vtkIdType start = points->GetNumberOfPoints();
    for (const V3& p : c.points)
    {
      const V3 d = sub(p, grid.lattice);
      lines->InsertCellPoint(
        points->InsertNextPoint(dot(frame.r, d) - grid.first[0], dot(frame.c, d) - grid.first[1], c.slice * h));
    }
    lines->InsertCellPoint(start); // closed
  }
  vtkNew<vtkPolyData> contours;
  contours->SetPoints(points);
  contours->SetLines(lines);
  vtkNew<vtkPolyDataToImageStencil> fill;
  fill->SetInputData(contours);
  fill->SetOutputOrigin(0.0, 0.0, 0.0);
  fill->SetOutputSpacing(grid.dx, grid.dy, h);
  fill->SetOutputWholeExtent(0, dims[0] - 1, 0, dims[1] - 1, 0, dims[2] - 1);
  fill->Update();
  vtkImageStencilData* stencil = fill->GetOutput();

  // The ROI's voxels from its first slice to its last: the contours'
  // slices filled, the slices between them interpolated (gaps of up to
  // twice its usual contour spacing; wider ones are left as they are).
  zFirst = *slices.begin();
  const int zLast = *slices.rbegin();
  std::vector<unsigned char> mask(static_cast<std::size_t>(sliceSize) * static_cast<std::size_t>(zLast - zFirst + 1), 0);
  auto sliceOf = [&](int z) { return mask.data() + static_cast<vtkIdType>(z - zFirst) * sliceSize; };
  for (int z : slices)
    for (int y = 0; y < dims[1]; ++y)
    {
      int iter = 0, r1 = 0, r2 = 0;
      unsigned char* row = sliceOf(z) + static_cast<vtkIdType>(y) * dims[0];
      while (stencil->GetNextExtent(r1, r2, 0, dims[0] - 1, y, z, iter))
        std::fill(row + r1, row + r2 + 1, static_cast<unsigned char>(1));
    }
  std::vector<int> steps;
  for (auto z = std::next(slices.begin()); z != slices.end(); ++z)
    steps.push_back(*z - *std::prev(z));
  int interpolated = 0, unbridged = 0;
  if (!steps.empty())
  {
    std::vector<int> sorted = steps;
    std::nth_element(sorted.begin(), sorted.begin() + static_cast<std::ptrdiff_t>(sorted.size() / 2), sorted.end());
    const int usual = sorted[sorted.size() / 2];
    // A contour between two gaps is the top of one and the bottom of the
    // next: its distance map is kept for the second.
    int mapped = -1;
    std::vector<float> above;
    for (auto z = std::next(slices.begin()); z != slices.end(); ++z)
    {
      const int a = *std::prev(z), b = *z;
      if (b - a < 2)
        continue;
      if (b - a > 2 * usual)
      {
        unbridged += b - a - 1;
        continue;
      }
      interpolated += b - a - 1;
      const std::vector<float> below = mapped == a ? std::move(above) : signedDistance(sliceOf(a), dims[0], dims[1]);
      above = signedDistance(sliceOf(b), dims[0], dims[1]);
      mapped = b;
      for (int t = a + 1; t < b; ++t)
      {
        const float w = static_cast<float>(t - a) / static_cast<float>(b - a);
        unsigned char* out = sliceOf(t);
        for (vtkIdType p = 0; p < sliceSize; ++p)
          out[p] = (1.0f - w) * below[static_cast<std::size_t>(p)] + w * above[static_cast<std::size_t>(p)] < 0.0f;
      }
    }
  }
  if (interpolated + unbridged > 0)
  {
    std::string note = "ROI '" + roi.name + "' has no contour on " + std::to_string(interpolated + unbridged) +
      " of the slices between its first and last (" + mm(h) + " apart): ";
    if (unbridged == 0)
      note += "they are filled by interpolating the contours on either side";
    else if (interpolated == 0)
      note += "its surface has gaps there (each over twice its usual contour spacing, not bridged)";
    else
      note += std::to_string(interpolated) + " are filled by interpolating the contours on either side; at the other " +
        std::to_string(unbridged) + ", in gaps over twice its usual contour spacing, its surface has gaps";
    notes.push_back(note);
  }
  return mask;
}

} // namespace

std::string referencedImageFile(const std::string& file, const std::vector<DICOMSeriesInfo>& series)
{
  vtkNew<vtkDICOMMetaData> meta;
  std::string ignored;
  if (!readDICOMHeader(file, meta, ignored))
    return std::string();
  DICOMSeriesInfo beside;
  const DICOMSeriesInfo* images = referencedImagesNear(meta, file, series, beside);
  return images ? images->files.front() : std::string();
}

std::vector<StructureSetInfo> findDICOMStructureSets(const std::string& folder, int scanDepth)
{
  std::vector<StructureSetInfo> found;
  vtkNew<vtkDICOMDirectory> dir;
  ErrorCatcher catcher(dir); // the image scan before it has said what is wrong with the folder
  dir->SetDirectoryName(folder.c_str());
  dir->SetScanDepth(std::max(1, scanDepth));
  dir->RequirePixelDataOff();
  vtkDICOMItem query;
  query.Set(DC::Modality, "RTSTRUCT");
  dir->SetFindQuery(query);
  updateDirectory(dir, nullptr, &catcher); // the image scan before it has warned of a stale DICOMDIR
  for (int s = 0; s < dir->GetNumberOfSeries(); ++s)
  {
    vtkStringArray* files = dir->GetFileNamesForSeries(s);
    for (vtkIdType f = 0; f < files->GetNumberOfValues(); ++f)
    {
      vtkNew<vtkDICOMMetaData> meta;
      std::string error;
      if (!readDICOMHeader(files->GetValue(f), meta, error) || meta->Get(DC::SOPClassUID).AsString() != kRTStructureSetStorage)
        continue;
      StructureSetInfo info;
      info.file = files->GetValue(f);
      info.referencedSeries = referencedSeriesUIDs(meta);
      const vtkDICOMValue& list = meta->Get(DC::StructureSetROISequence);
      for (unsigned int i = 0; i < itemCount(list); ++i)
        info.roiNames.push_back(dicomText(list.GetSequenceData()[i].Get(DC::ROIName)));
      found.push_back(info);
    }
  }
  return found;
}

std::vector<StructureSetInfo> findDICOMStructureSetsBeside(const std::string& folder, const std::string& imageFile)
{
  std::vector<StructureSetInfo> found;
  vtkNew<vtkDICOMMetaData> image;
  std::string ignored;
  if (!imageFile.empty())
    readDICOMHeader(imageFile, image, ignored);
  const StudyKeys keys(image);
  for (const FolderBeside& beside : foldersBeside(folder))
    if (beside.modality == "RTSTRUCT" || keys.share(beside))
    {
      const std::vector<StructureSetInfo> sets = findDICOMStructureSets(beside.folder, 1);
      found.insert(found.end(), sets.begin(), sets.end());
    }
  return found;
}

bool isDICOMStructureSet(const std::string& file)
{
  // A file cut short still says what it is (its SOP class comes first):
  // reading it then says what is wrong.
  vtkNew<vtkDICOMMetaData> meta;
  std::string error;
  readDICOMHeader(file, meta, error);
  return meta->Get(DC::SOPClassUID).AsString() == kRTStructureSetStorage;
}

bool readDICOMStructureSet(const std::string& file, const std::vector<DICOMSeriesInfo>& imageSeries,
  vtkImageData* output, vtkMatrix4x4* patientMatrix, std::vector<Segment>& segments,
  std::vector<std::string>& notes, std::string& referencedImage, std::string& error, vtkAlgorithm* progress)
{
  segments.clear();
  notes.clear();
  referencedImage.clear();
  vtkNew<vtkDICOMMetaData> meta;
  if (!readDICOMHeader(file, meta, error))
    return false;
  if (meta->Get(DC::SOPClassUID).AsString() != kRTStructureSetStorage)
  {
    error = "'" + file + "' is not an RT structure set";
    return false;
  }
  DICOMSeriesInfo beside;
  bool crowded = false;
  const DICOMSeriesInfo* images = referencedImagesNear(meta, file, imageSeries, beside, &crowded);
  if (images)
    referencedImage = images->files.front();
  std::vector<ROI> rois;
  int skippedShort = 0;
  if (!readROIs(meta, rois, skippedShort, error))
    return false;
  std::vector<std::string> without;
  for (const ROI& roi : rois)
    if (roi.contours.empty())
    {
      std::string types;
      for (const std::string& t : roi.otherTypes)
        types += (types.empty() ? "" : ", ") + t;
      without.push_back("'" + roi.name + "'" + (types.empty() ? std::string(" (no contours)") : " (" + types + ")"));
    }
  rois.erase(std::remove_if(rois.begin(), rois.end(), [](const ROI& roi) { return roi.contours.empty(); }), rois.end());
  if (rois.empty())
  {
    error = "no ROI of the RT structure set has closed planar contours";
    if (!without.empty())
    {
      error += ":";
      for (const std::string& w : without)
        error += " " + w;
    }
    return false;
  }
  if (!without.empty())
  {
    std::string note = "ROIs without closed planar contours are not read:";
    for (const std::string& w : without)
      note += " " + w;
    notes.push_back(note);
  }
  if (skippedShort > 0)
    notes.push_back(std::to_string(skippedShort) + " contour" + (skippedShort == 1 ? " has" : "s have") +
      " fewer than 3 points and " + (skippedShort == 1 ? "is" : "are") + " not read");

  Grid grid;
  if (!placeGrid(meta, images, crowded, rois, grid, notes, error))
    return false;
  const vtkIdType voxels = static_cast<vtkIdType>(grid.dims[0]) * grid.dims[1] * grid.dims[2];

  // Labels: the ROI numbers, unless one does not fit a label.
  const bool numbered = std::all_of(
    rois.begin(), rois.end(), [](const ROI& roi) { return roi.number >= 1 && roi.number <= 65535; });
  if (!numbered)
    notes.push_back("ROINumbers outside 1 to 65535: the ROIs are labelled 1 to " + std::to_string(rois.size()) +
      " in their order instead");

  // Each ROI filled, then put in the first layer it does not overlap.
  std::vector<std::vector<unsigned short>> layers;
  int largest = 0;
  for (std::size_t i = 0; i < rois.size(); ++i)
  {
    if (progress)
    {
      progress->UpdateProgress(0.2 + 0.8 * static_cast<double>(i) / static_cast<double>(rois.size()));
      if (progress->GetAbortExecute())
        break;
    }
    int zFirst = 0;
    const std::vector<unsigned char> mask = fillROI(rois[i], grid, zFirst, notes);
    const int label = numbered ? rois[i].number : static_cast<int>(i) + 1;
    largest = std::max(largest, label);
    const vtkIdType offset = static_cast<vtkIdType>(zFirst) * grid.dims[0] * grid.dims[1];
    const vtkIdType span = static_cast<vtkIdType>(mask.size());
    const int l = layerFor(layers, voxels, [&](const std::vector<unsigned short>& layer) {
      for (vtkIdType v = 0; v < span; ++v)
        if (mask[static_cast<std::size_t>(v)] && layer[static_cast<std::size_t>(offset + v)] != 0)
          return false;
      return true;
    });
    if (l < 0)
    {
      error = "the RT structure set's ROIs overlap in more layers than fit in memory";
      return false;
    }
    unsigned short* layer = layers[static_cast<std::size_t>(l)].data() + offset;
    for (vtkIdType v = 0; v < span; ++v)
      if (mask[static_cast<std::size_t>(v)])
        layer[v] = static_cast<unsigned short>(label);
    segments.push_back({ label, rois[i].name, l });
  }
  if (layers.empty()) // stopped before the first ROI
    layers.emplace_back(static_cast<std::size_t>(voxels), 0);
  const double spacing[3] = { grid.dx, grid.dy, grid.h };
  setLayers(output, grid.dims, spacing, layers, std::max(largest, 1));
  const SliceFrame& f = grid.frame;
  V3 corner;
  for (std::size_t a = 0; a < 3; ++a)
    corner[a] = grid.lattice[a] - dot(f.n, grid.lattice) * f.n[a] + grid.first[0] * f.r[a] + grid.first[1] * f.c[a] +
      grid.z0 * f.n[a];
  setPatientMatrix(patientMatrix, f, corner);
  return true;
}

} // namespace lkvtk
