#include "latticekit/BezierIFS.h"

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <string>

namespace lk
{
namespace
{
double binomial(int n, int k)
{
  double r = 1.0;
  for (int i = 1; i <= k; ++i)
    r = r * (n - k + i) / i;
  return r;
}

std::vector<std::pair<double, double>> intervals(const std::vector<double>& breaks)
{
  if (breaks.size() >= kMaximumIfsMaps)
    throw std::invalid_argument(std::to_string(breaks.size() + 1) + " maps are more than an IFS may have (" +
      std::to_string(kMaximumIfsMaps) + ")");
  double last = 0.0;
  std::vector<std::pair<double, double>> out;
  for (double b : breaks)
  {
    if (!(b > last && b < 1.0))
      throw std::invalid_argument("split parameters must increase strictly inside (0, 1); got " + std::to_string(b));
    out.emplace_back(last, b);
    last = b;
  }
  if (breaks.empty())
    throw std::invalid_argument("an IFS needs at least one split parameter (two maps)");
  out.emplace_back(last, 1.0);
  return out;
}

/// M with B(a + s t) = M B(t): solved from n + 1 sample parameters.
Eigen::MatrixXd subdivisionMatrix(int n, double a, double s)
{
  Eigen::MatrixXd X(n + 1, n + 1), Y(n + 1, n + 1);
  for (int k = 0; k <= n; ++k)
  {
    const double t = n == 0 ? 0.0 : double(k) / n;
    X.col(k) = bernsteinCurve(n, t);
    Y.col(k) = bernsteinCurve(n, a + s * t);
  }
  return Y * X.inverse();
}

void checkDegree(int n)
{
  if (n < 1 || n > 20)
    throw std::invalid_argument("the degree must lie in 1..20, not " + std::to_string(n));
}
} // namespace

Eigen::VectorXd bernsteinCurve(int n, double t)
{
  Eigen::VectorXd b(n + 1);
  for (int i = 0; i <= n; ++i)
    b[i] = binomial(n, i) * std::pow(1.0 - t, n - i) * std::pow(t, i);
  return b;
}

Eigen::VectorXd bernsteinSurface(int n, int m, double u, double v)
{
  const Eigen::VectorXd bu = bernsteinCurve(n, u), bv = bernsteinCurve(m, v);
  Eigen::VectorXd b((n + 1) * (m + 1));
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j)
      b[i * (m + 1) + j] = bu[i] * bv[j];
  return b;
}

std::vector<IfsMap> bernsteinCurveMaps(int degree, const std::vector<double>& breaks)
{
  checkDegree(degree);
  std::vector<IfsMap> maps;
  for (const auto& [a, b] : intervals(breaks))
  {
    const double s = b - a;
    IfsMap w;
    const Eigen::MatrixXd M = subdivisionMatrix(degree, a, s);
    // 1 - s as a + (1 - b), the parameter outside [a, b]: computed as 1 - s
    // it is 0 for a break within rounding of 0 or 1 (1e-300), and a / 0 made
    // every point NaN.
    const double rest = a + (1.0 - b);
    w.c = rest * bernsteinCurve(degree, a / rest);
    w.A = M - w.c * Eigen::RowVectorXd::Ones(degree + 1);
    w.a[0] = a;
    w.s[0] = s;
    w.s[1] = 1.0;
    maps.push_back(std::move(w));
  }
  return maps;
}

std::vector<IfsMap> bernsteinSurfaceMaps(int n, int m, const std::vector<double>& breaks)
{
  checkDegree(n);
  checkDegree(m);
  const auto iv = intervals(breaks);
  const double count = static_cast<double>(iv.size()) * static_cast<double>(iv.size());
  if (count > static_cast<double>(kMaximumIfsMaps))
    throw std::invalid_argument(std::to_string(iv.size()) + " x " + std::to_string(iv.size()) +
      " maps are more than an IFS may have (" + std::to_string(kMaximumIfsMaps) + ")");
  const double values = static_cast<double>((n + 1) * (m + 1));
  if (count * values * values * sizeof(double) > 1e9)
    throw std::invalid_argument("the " + std::to_string(static_cast<long long>(count)) + " maps of a degree " +
      std::to_string(n) + " x " + std::to_string(m) + " net would take more than 1 GB: use fewer maps or a lower degree");
  std::vector<IfsMap> maps;
  for (const auto& [au, bu] : iv)
  {
    for (const auto& [av, bv] : iv)
    {
      const double su = bu - au, sv = bv - av;
      const Eigen::MatrixXd Mu = subdivisionMatrix(n, au, su), Mv = subdivisionMatrix(m, av, sv);
      const int N = (n + 1) * (m + 1);
      Eigen::MatrixXd M(N, N);
      for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= m; ++j)
          for (int k = 0; k <= n; ++k)
            for (int l = 0; l <= m; ++l)
              M(i * (m + 1) + j, k * (m + 1) + l) = Mu(i, k) * Mv(j, l);
      IfsMap w;
      const double restU = au + (1.0 - bu), restV = av + (1.0 - bv); // 1 - su, 1 - sv (as for curves)
      w.c = (1.0 - su * sv) * bernsteinSurface(n, m, au / restU, av / restV);
      w.A = M - w.c * Eigen::RowVectorXd::Ones(N);
      w.a[0] = au;
      w.a[1] = av;
      w.s[0] = su;
      w.s[1] = sv;
      maps.push_back(std::move(w));
    }
  }
  return maps;
}

Vec3 deCasteljau(const std::vector<Vec3>& control, double t)
{
  std::vector<Vec3> p = control;
  for (std::size_t r = 1; r < p.size(); ++r)
    for (std::size_t i = 0; i + r < p.size(); ++i)
      p[i] = (1.0 - t) * p[i] + t * p[i + 1];
  return p.empty() ? Vec3::Zero() : p[0];
}

Vec3 deCasteljauSurface(const std::vector<Vec3>& control, int n, int m, double u, double v)
{
  std::vector<Vec3> rows;
  for (int i = 0; i <= n; ++i)
    rows.push_back(deCasteljau(std::vector<Vec3>(control.begin() + i * (m + 1), control.begin() + (i + 1) * (m + 1)), v));
  return deCasteljau(rows, u);
}

std::vector<IfsMap> quadraticPlanarMaps(const std::vector<Vec3>& P, double t)
{
  if (P.size() != 3)
    throw std::invalid_argument("the direct IFS of section 4 takes a quadratic curve: 3 control points");
  if (!(t > 0.0 && t < 1.0))
    throw std::invalid_argument("the split parameter must lie in (0, 1)");
  const Vec3 e1 = P[1] - P[0], e2 = P[2] - P[0];
  const Vec3 nrm = e1.cross(e2);
  if (!(nrm.norm() > 1e-12 * e1.norm() * e2.norm()))
    throw std::invalid_argument("the control points are collinear: they span no plane for the affine maps");
  const Vec3 q01 = (1 - t) * P[0] + t * P[1], q12 = (1 - t) * P[1] + t * P[2];
  const Vec3 mid = (1 - t) * q01 + t * q12;
  const std::vector<Vec3> halves[2] = { { P[0], q01, mid }, { mid, q12, P[2] } };
  Eigen::Matrix3d E;
  E << e1, e2, nrm.normalized();
  const Eigen::Matrix3d Einv = E.inverse();
  std::vector<IfsMap> maps;
  for (int h = 0; h < 2; ++h)
  {
    const auto& L = halves[h];
    Eigen::Matrix3d img;
    img << L[1] - L[0], L[2] - L[0], Vec3::Zero();
    IfsMap w;
    w.A = img * Einv;
    w.c = L[0] - w.A * P[0];
    w.a[0] = h == 0 ? 0.0 : t;
    w.s[0] = h == 0 ? t : 1.0 - t;
    maps.push_back(std::move(w));
  }
  return maps;
}

double spectralRadius(const IfsMap& map)
{
  Eigen::EigenSolver<Eigen::MatrixXd> es(map.A);
  return es.eigenvalues().cwiseAbs().maxCoeff();
}

namespace
{
Vec3 plot(const Eigen::VectorXd& x, const std::vector<Vec3>& control)
{
  if (control.empty())
    return Vec3(x[0], x[1], x[2]);
  Vec3 p = Vec3::Zero();
  for (std::size_t i = 0; i < control.size(); ++i)
    p += x[static_cast<Eigen::Index>(i)] * control[i];
  return p;
}
} // namespace

IfsPoints deterministicIfs(const std::vector<IfsMap>& maps, const std::vector<Eigen::VectorXd>& base,
  const std::vector<std::array<double, 2>>& baseParameters, int depth, const std::vector<Vec3>& control)
{
  if (depth < 0)
    throw std::invalid_argument("the depth must be at least 0, not " + std::to_string(depth));
  if (const double points = std::pow(double(maps.size()), depth) * double(base.size()); points > 5e7)
  {
    char text[200];
    std::snprintf(text, sizeof text,
      "%zu maps to depth %d give %.3g points (%zu^%d x %zu), more than 50 million: lower the depth or the number of maps",
      maps.size(), depth, points, maps.size(), depth, base.size());
    throw std::invalid_argument(text);
  }
  std::vector<Eigen::VectorXd> figs = base;
  std::vector<std::array<double, 2>> params = baseParameters;
  for (int d = 0; d < depth; ++d)
  {
    std::vector<Eigen::VectorXd> next;
    std::vector<std::array<double, 2>> nextParams;
    next.reserve(figs.size() * maps.size());
    for (const IfsMap& w : maps)
    {
      for (std::size_t i = 0; i < figs.size(); ++i)
      {
        next.push_back(w.A * figs[i] + w.c);
        nextParams.push_back({ w.a[0] + w.s[0] * params[i][0], w.a[1] + w.s[1] * params[i][1] });
      }
    }
    figs.swap(next);
    params.swap(nextParams);
  }
  IfsPoints out;
  out.parameters = params;
  out.points.reserve(figs.size());
  for (const auto& x : figs)
    out.points.push_back(plot(x, control));
  return out;
}

IfsPoints chaosGame(const std::vector<IfsMap>& maps, const std::vector<double>& probabilities,
  const Eigen::VectorXd& start, std::array<double, 2> param, std::size_t count, std::uint64_t seed,
  const std::vector<Vec3>& control)
{
  if (probabilities.size() != maps.size())
    throw std::invalid_argument("the chaos game needs one probability per map (" + std::to_string(maps.size()) +
      "), not " + std::to_string(probabilities.size()));
  double sum = 0.0;
  for (double p : probabilities)
  {
    if (!(p >= 0.0 && std::isfinite(p)))
      throw std::invalid_argument("map probabilities must be finite and >= 0");
    sum += p;
  }
  if (!(std::abs(sum - 1.0) < 1e-9))
    throw std::invalid_argument("map probabilities must sum to 1, not " + std::to_string(sum));
  std::vector<double> cumulative;
  double acc = 0.0;
  for (double p : probabilities)
    cumulative.push_back(acc += p);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  IfsPoints out;
  out.points.reserve(count);
  out.parameters.reserve(count);
  Eigen::VectorXd x = start, y(start.size());
  for (std::size_t k = 0; k < count; ++k)
  {
    const double r = uniform(rng);
    std::size_t i = 0;
    while (i + 1 < maps.size() && r >= cumulative[i])
      ++i;
    const IfsMap& w = maps[i];
    y.noalias() = w.A * x;
    y += w.c;
    x.swap(y);
    param = { w.a[0] + w.s[0] * param[0], w.a[1] + w.s[1] * param[1] };
    out.points.push_back(plot(x, control));
    out.parameters.push_back(param);
  }
  return out;
}

} // namespace lk
