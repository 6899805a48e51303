#include "latticekit/WrinklySurface.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace lk
{
namespace
{

/// Degree elevation 2 -> 3: cubic point k from quadratic points.
constexpr double kElevate[4][3] = { { 1.0, 0.0, 0.0 }, { 1.0 / 3.0, 2.0 / 3.0, 0.0 },
  { 0.0, 2.0 / 3.0, 1.0 / 3.0 }, { 0.0, 0.0, 1.0 } };

inline void bernstein3(double t, double b[4])
{
  const double s = 1.0 - t;
  b[0] = s * s * s;
  b[1] = 3.0 * t * s * s;
  b[2] = 3.0 * t * t * s;
  b[3] = t * t * t;
}

inline void bernstein3Derivative(double t, double d[4])
{
  const double s = 1.0 - t;
  d[0] = -3.0 * s * s;
  d[1] = 3.0 * s * s - 6.0 * t * s;
  d[2] = 6.0 * t * s - 3.0 * t * t;
  d[3] = 3.0 * t * t;
}

WrinklyParameters checked(const WrinklyParameters& p)
{
  if (!(p.alpha0 >= 0.0 && p.alpha0 <= 1.0 && p.alpha1 >= 0.0 && p.alpha1 <= 1.0) ||
    std::abs(p.alpha0 + p.alpha1 - 1.0) > 1e-9)
    throw std::invalid_argument("alpha0 and alpha1 must lie in [0, 1] and add up to 1 (eq. 12), not " +
      std::to_string(p.alpha0) + " and " + std::to_string(p.alpha1));
  return p;
}

} // namespace

WrinklySurface::WrinklySurface(const WrinklyControlMesh& mesh, const WrinklyParameters& parameters)
  : axes_(buildWrinklyGlobalAxes(mesh))
  , parameters_(checked(parameters))
  , shuffle_{ { IteratedShuffle(parameters.shuffleU, parameters.iterations),
      IteratedShuffle(parameters.shuffleV, parameters.iterations) } }
{
  attributeComponents_ = mesh.attributeComponents;
  channels_ = 4 + attributeComponents_;
  const int np = static_cast<int>(mesh.points.size());
  std::vector<double> value(static_cast<std::size_t>(np) * channels_, 0.0);
  for (int i = 0; i < np; ++i)
  {
    double* v = &value[static_cast<std::size_t>(i) * channels_];
    v[0] = mesh.points[i].x();
    v[1] = mesh.points[i].y();
    v[2] = mesh.points[i].z();
    v[3] = mesh.heights.empty() ? 0.0 : mesh.heights[i];
    if (!std::isfinite(v[3]))
      throw std::invalid_argument("the height of control point " + std::to_string(i) + " is not finite");
    for (int c = 0; c < attributeComponents_; ++c)
    {
      v[4 + c] = mesh.attributes[static_cast<std::size_t>(i) * attributeComponents_ + c];
      if (!std::isfinite(v[4 + c]))
        throw std::invalid_argument("an attribute of control point " + std::to_string(i) + " is not finite");
    }
  }
  std::vector<double> centroid(mesh.faces.size() * channels_, 0.0);
  for (std::size_t f = 0; f < mesh.faces.size(); ++f)
  {
    for (int p : mesh.faces[f])
      for (int c = 0; c < channels_; ++c)
        centroid[f * channels_ + c] += value[static_cast<std::size_t>(p) * channels_ + c];
    for (int c = 0; c < channels_; ++c)
      centroid[f * channels_ + c] /= static_cast<double>(mesh.faces[f].size());
  }

  patchIndex_.assign(np, -1);
  const std::size_t patches = axes_.patchPoints.size();
  control_.assign(patches * 16 * channels_, 0.0);
  orientation_.assign(patches, 1.0);
  std::vector<double> net(9 * channels_);
  for (std::size_t pi = 0; pi < patches; ++pi)
  {
    const int n = axes_.patchPoints[pi];
    patchIndex_[n] = static_cast<int>(pi);
    const WrinklyFrame& fr = axes_.frames[n];
    // The biquadratic net: net[i][j], i along u, j along v.
    auto copy = [&](int i, int j, const double* from) {
      std::copy(from, from + channels_, &net[(i * 3 + j) * channels_]);
    };
    auto cellValue = [&](int cell) { return &centroid[static_cast<std::size_t>(cell) * channels_]; };
    auto pointValue = [&](int q) { return &value[static_cast<std::size_t>(q) * channels_]; };
    auto edge = [&](int i, int j, int role) {
      if (fr.link[role] < 0) // missing link: its side collapses onto the cell that holds it
        return copy(i, j, cellValue(fr.missingCell[role]));
      double* b = &net[(i * 3 + j) * channels_];
      for (int c = 0; c < channels_; ++c)
        b[c] = 0.5 * (pointValue(n)[c] + pointValue(fr.link[role])[c]);
    };
    copy(0, 0, cellValue(fr.corner[0]));
    copy(2, 0, cellValue(fr.corner[1]));
    copy(0, 2, cellValue(fr.corner[2]));
    copy(2, 2, cellValue(fr.corner[3]));
    edge(1, 0, MinusV);
    edge(1, 2, PlusV);
    edge(0, 1, MinusU);
    edge(2, 1, PlusU);
    copy(1, 1, pointValue(n));
    double* out = &control_[pi * 16 * channels_];
    for (int k = 0; k < 4; ++k)
      for (int l = 0; l < 4; ++l)
        for (int c = 0; c < channels_; ++c)
        {
          double s = 0.0;
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
              s += kElevate[k][i] * kElevate[l][j] * net[(i * 3 + j) * channels_ + c];
          out[(k * 4 + l) * channels_ + c] = s;
        }
    // Orientation: the patch normal at its centre against the cells' normal
    // (Newell) around the point.
    Vec3 reference = Vec3::Zero();
    for (int cell : fr.corner)
    {
      const auto& face = mesh.faces[cell];
      for (std::size_t a = 0; a < face.size(); ++a)
        reference += mesh.points[face[a]].cross(mesh.points[face[(a + 1) % face.size()]]);
    }
    const auto [pu, pv] = partials(static_cast<int>(pi), 0.5, 0.5);
    const Vec3 normal = pu.cross(pv);
    orientation_[pi] = normal.dot(reference) < 0.0 ? -1.0 : 1.0;
  }
}

void WrinklySurface::setIterations(int iterations)
{
  shuffle_ = { { IteratedShuffle(parameters_.shuffleU, iterations), IteratedShuffle(parameters_.shuffleV, iterations) } };
  parameters_.iterations = iterations;
}

int WrinklySurface::patchOf(int point) const
{
  if (point < 0 || point >= static_cast<int>(patchIndex_.size()) || patchIndex_[point] < 0)
    throw std::invalid_argument("control point " + std::to_string(point) + " has no patch (virtual or unknown)");
  return patchIndex_[point];
}

void WrinklySurface::evaluate(int patch, int channel0, int channels, double u, double v, double* out) const
{
  std::fill(out, out + channels, 0.0);
  accumulate(patch, channel0, channels, u, v, 1.0, out);
}

void WrinklySurface::accumulate(
  int patch, int channel0, int channels, double u, double v, double weight, double* out) const
{
  double bu[4], bv[4];
  bernstein3(u, bu);
  bernstein3(v, bv);
  const double* c = &control_[static_cast<std::size_t>(patch) * 16 * channels_];
  for (int k = 0; k < 4; ++k)
    for (int l = 0; l < 4; ++l)
    {
      const double w = weight * bu[k] * bv[l];
      const double* p = c + (k * 4 + l) * channels_ + channel0;
      for (int ch = 0; ch < channels; ++ch)
        out[ch] += w * p[ch];
    }
}

std::pair<Vec3, Vec3> WrinklySurface::partials(int patch, double u, double v) const
{
  double bu[4], bv[4], du[4], dv[4];
  bernstein3(u, bu);
  bernstein3(v, bv);
  bernstein3Derivative(u, du);
  bernstein3Derivative(v, dv);
  const double* c = &control_[static_cast<std::size_t>(patch) * 16 * channels_];
  Vec3 pu = Vec3::Zero(), pv = Vec3::Zero();
  for (int k = 0; k < 4; ++k)
    for (int l = 0; l < 4; ++l)
    {
      const double* q = c + (k * 4 + l) * channels_;
      const Vec3 p(q[0], q[1], q[2]);
      pu += du[k] * bv[l] * p;
      pv += bu[k] * dv[l] * p;
    }
  return { pu, pv };
}

std::array<Vec3, 16> WrinklySurface::basePatch(int point) const
{
  const int patch = patchOf(point);
  std::array<Vec3, 16> out;
  const double* c = &control_[static_cast<std::size_t>(patch) * 16 * channels_];
  for (int i = 0; i < 16; ++i)
    out[i] = Vec3(c[i * channels_], c[i * channels_ + 1], c[i * channels_ + 2]);
  return out;
}

Vec3 WrinklySurface::basePoint(const WrinklyLocal& t) const
{
  double p[3];
  evaluate(patchOf(t.point), 0, 3, t.u, t.v, p);
  return Vec3(p[0], p[1], p[2]);
}

Vec3 WrinklySurface::baseNormal(const WrinklyLocal& t) const
{
  const int patch = patchOf(t.point);
  const double* c = &control_[static_cast<std::size_t>(patch) * 16 * channels_];
  double u = t.u, v = t.v;
  double scale = 0.0;
  for (int i = 1; i < 16; ++i)
    for (int a = 0; a < 3; ++a)
      scale = std::max(scale, std::abs(c[i * channels_ + a] - c[a]));
  for (int attempt = 0; attempt < 8; ++attempt)
  {
    const auto [pu, pv] = partials(patch, u, v);
    const Vec3 n = pu.cross(pv);
    if (n.norm() > 1e-12 * scale * scale)
      return orientation_[patch] * n.normalized();
    u = 0.5 + (u - 0.5) * 0.9;
    v = 0.5 + (v - 0.5) * 0.9;
  }
  return Vec3::UnitZ();
}

double WrinklySurface::patchOrientation(int point) const
{
  return orientation_[patchOf(point)];
}

double WrinklySurface::height(const WrinklyLocal& t) const
{
  double h;
  evaluate(patchOf(t.point), 3, 1, t.u, t.v, &h);
  return h;
}

void WrinklySurface::attributes(const WrinklyLocal& t, double* out) const
{
  evaluate(patchOf(t.point), 4, attributeComponents_, t.u, t.v, out);
}

WrinklyLocal WrinklySurface::inverseStep(int group, const WrinklyLocal& t) const
{
  const WrinklyFrame& fr = axes_.frames[t.point];
  const WrinklyAxis& axis = axes_.axes[group][fr.axis[group]];
  const int k = fr.index[group];
  const double along = group == 0 ? t.u : t.v;
  const double across = group == 0 ? t.v : t.u;
  const double length = static_cast<double>(axis.points.size());
  double x = shuffle_[group].inverse(k + along);
  if (axis.cyclic)
  {
    x = std::fmod(x, length);
    if (x < 0.0)
      x += length;
    if (x >= length)
      x = 0.0;
  }
  else
    x = IteratedShuffle::mirrorInto(x, length);
  int k2 = static_cast<int>(std::floor(x));
  k2 = std::clamp(k2, 0, static_cast<int>(axis.points.size()) - 1);
  const double along2 = x - k2;
  const double onChain = axis.crossFlip[k] ? 1.0 - across : across;
  const double across2 = axis.crossFlip[k2] ? 1.0 - onChain : onChain;
  WrinklyLocal r;
  r.point = axis.points[k2];
  r.u = group == 0 ? along2 : across2;
  r.v = group == 0 ? across2 : along2;
  return r;
}

WrinklyLocal WrinklySurface::inverseShuffle(int order, const WrinklyLocal& t) const
{
  // F_(U->V) = F_V o F_U, so its inverse steps along V first.
  return order == 0 ? inverseStep(0, inverseStep(1, t)) : inverseStep(1, inverseStep(0, t));
}

double WrinklySurface::wrinklyHeight(const WrinklyLocal& t) const
{
  double h = 0.0;
  if (parameters_.alpha0 > 0.0)
    h += parameters_.alpha0 * height(inverseShuffle(0, t));
  if (parameters_.alpha1 > 0.0)
    h += parameters_.alpha1 * height(inverseShuffle(1, t));
  return h;
}

void WrinklySurface::wrinklyAttributes(const WrinklyLocal& t, double* out) const
{
  std::fill(out, out + attributeComponents_, 0.0);
  const double alpha[2] = { parameters_.alpha0, parameters_.alpha1 };
  for (int order = 0; order < 2; ++order)
  {
    if (alpha[order] <= 0.0)
      continue;
    const WrinklyLocal source = inverseShuffle(order, t);
    accumulate(patchOf(source.point), 4, attributeComponents_, source.u, source.v, alpha[order], out);
  }
}

Vec3 WrinklySurface::surfacePoint(const WrinklyLocal& t) const
{
  return basePoint(t) + wrinklyHeight(t) * baseNormal(t);
}

double WrinklySurface::largestPatchSize() const
{
  double size = 0.0;
  for (std::size_t p = 0; p < axes_.patchPoints.size(); ++p)
  {
    const double* c = &control_[p * 16 * channels_];
    Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
    for (int i = 0; i < 16; ++i)
    {
      const Vec3 q(c[i * channels_], c[i * channels_ + 1], c[i * channels_ + 2]);
      lo = lo.cwiseMin(q);
      hi = hi.cwiseMax(q);
    }
    size = std::max(size, (hi - lo).norm());
  }
  return size;
}

int wrinklyIterationsForTolerance(const WrinklySurface& surface, double tolerance, int maxIterations)
{
  if (!(tolerance > 0.0) || !std::isfinite(tolerance))
    throw std::invalid_argument("the sampling tolerance must be a positive length");
  const int n = 2 * std::min(surface.parameters().shuffleU, surface.parameters().shuffleV) + 1;
  double piece = surface.largestPatchSize();
  int k = 0;
  while (piece > tolerance && k < maxIterations && n > 1)
  {
    piece /= n;
    ++k;
  }
  return k;
}

WrinklyTessellation tessellateWrinkly(
  const WrinklySurface& surface, int resolution, const std::function<bool(double)>& progress)
{
  if (resolution < 1)
    throw std::invalid_argument("the tessellation resolution must be at least 1");
  const auto& patches = surface.patchPoints();
  const double triangles = 2.0 * resolution * static_cast<double>(resolution) * patches.size();
  if (triangles > 5e7)
    throw std::invalid_argument("the tessellation would have " + std::to_string(static_cast<long long>(triangles)) +
      " triangles (limit 50 million); use fewer iterations or a lower resolution");
  const int ac = surface.attributeComponents();
  WrinklyTessellation out;
  const std::size_t perPatch = static_cast<std::size_t>(resolution + 1) * (resolution + 1);
  out.points.reserve(patches.size() * perPatch);
  out.triangles.reserve(static_cast<std::size_t>(triangles));

  // Border samples are merged by their base-surface position.
  const double quantum = std::max(surface.largestPatchSize(), 1e-300) * 1e-9;
  struct KeyHash
  {
    std::size_t operator()(const std::array<long long, 3>& k) const
    {
      return static_cast<std::size_t>(k[0] * 73856093LL ^ k[1] * 19349663LL ^ k[2] * 83492791LL);
    }
  };
  std::unordered_map<std::array<long long, 3>, int, KeyHash> border;
  std::vector<int> ids(perPatch);
  std::vector<double> attr(ac);
  const double half = 0.5 / resolution;
  for (std::size_t pi = 0; pi < patches.size(); ++pi)
  {
    const int n = patches[pi];
    const bool flip = surface.patchOrientation(n) < 0.0;
    for (int a = 0; a <= resolution; ++a)
    {
      for (int b = 0; b <= resolution; ++b)
      {
        WrinklyLocal t{ n, static_cast<double>(a) / resolution, static_cast<double>(b) / resolution };
        const Vec3 base = surface.basePoint(t);
        const bool onBorder = a == 0 || b == 0 || a == resolution || b == resolution;
        int id = -1;
        std::array<long long, 3> key{};
        if (onBorder)
        {
          for (int d = 0; d < 3; ++d)
            key[d] = std::llround(base[d] / quantum);
          const auto it = border.find(key);
          if (it != border.end())
            id = it->second;
        }
        if (id < 0)
        {
          id = static_cast<int>(out.points.size());
          const WrinklyLocal sample{ n, t.u + half, t.v + half };
          const double h = surface.wrinklyHeight(sample);
          const Vec3 normal = surface.baseNormal(t);
          out.points.push_back(base + h * normal);
          out.normals.push_back(normal);
          out.heights.push_back(h);
          if (ac > 0)
          {
            surface.wrinklyAttributes(sample, attr.data());
            out.attributes.insert(out.attributes.end(), attr.begin(), attr.end());
          }
          if (onBorder)
            border.emplace(key, id);
        }
        ids[static_cast<std::size_t>(a) * (resolution + 1) + b] = id;
      }
    }
    for (int a = 0; a < resolution; ++a)
      for (int b = 0; b < resolution; ++b)
      {
        const int p00 = ids[a * (resolution + 1) + b], p10 = ids[(a + 1) * (resolution + 1) + b];
        const int p01 = ids[a * (resolution + 1) + b + 1], p11 = ids[(a + 1) * (resolution + 1) + b + 1];
        auto add = [&](int x, int y, int z) {
          if (x == y || y == z || x == z)
            return;
          if (flip)
            std::swap(y, z);
          out.triangles.push_back({ { x, y, z } });
          out.trianglePoint.push_back(n);
        };
        add(p00, p10, p11);
        add(p00, p11, p01);
      }
    if (progress && !progress(static_cast<double>(pi + 1) / patches.size()))
      return {};
  }
  return out;
}

} // namespace lk
