#include "latticekit/GregoryPatch.h"

#include <cmath>

namespace lk
{

namespace
{
void bernstein(double t, double b[4], double d[4])
{
  const double s = 1.0 - t;
  b[0] = s * s * s;
  b[1] = 3.0 * t * s * s;
  b[2] = 3.0 * t * t * s;
  b[3] = t * t * t;
  d[0] = -3.0 * s * s;
  d[1] = 3.0 * s * s - 6.0 * t * s;
  d[2] = 6.0 * t * s - 3.0 * t * t;
  d[3] = 3.0 * t * t;
}

/// (a A + b B) / (a + b) and its derivatives with respect to a and b.
/// At a = b = 0 (a patch corner, where the Bernstein weights vanish) the
/// midpoint and zero derivatives are returned.
Vec3 blend(double a, double b, const Vec3& A, const Vec3& B, Vec3& da, Vec3& db)
{
  const double s = a + b;
  if (s <= 0.0)
  {
    da.setZero();
    db.setZero();
    return 0.5 * (A + B);
  }
  da = b * (A - B) / (s * s);
  db = a * (B - A) / (s * s);
  return (a * A + b * B) / s;
}
} // namespace

Vec3 GregoryPatch::evaluate(double u, double v, Vec3* du, Vec3* dv) const
{
  double bu[4], bv[4], dbu[4], dbv[4];
  bernstein(u, bu, dbu);
  bernstein(v, bv, dbv);
  // Q_ij and its partial derivatives.
  Vec3 Q[4][4], Qu[4][4], Qv[4][4];
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      Q[i][j] = P(i, j);
      Qu[i][j].setZero();
      Qv[i][j].setZero();
    }
  }
  Vec3 da, db;
  Q[1][1] = blend(u, v, inner(1, 1, 0), inner(1, 1, 1), da, db);
  Qu[1][1] = da;
  Qv[1][1] = db;
  Q[1][2] = blend(u, 1.0 - v, inner(1, 2, 0), inner(1, 2, 1), da, db);
  Qu[1][2] = da;
  Qv[1][2] = -db;
  Q[2][1] = blend(1.0 - u, v, inner(2, 1, 0), inner(2, 1, 1), da, db);
  Qu[2][1] = -da;
  Qv[2][1] = db;
  Q[2][2] = blend(1.0 - u, 1.0 - v, inner(2, 2, 0), inner(2, 2, 1), da, db);
  Qu[2][2] = -da;
  Qv[2][2] = -db;

  Vec3 s = Vec3::Zero(), su = Vec3::Zero(), sv = Vec3::Zero();
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      s += bu[i] * bv[j] * Q[i][j];
      su += dbu[i] * bv[j] * Q[i][j] + bu[i] * bv[j] * Qu[i][j];
      sv += bu[i] * dbv[j] * Q[i][j] + bu[i] * bv[j] * Qv[i][j];
    }
  }
  if (du)
  {
    *du = su;
  }
  if (dv)
  {
    *dv = sv;
  }
  return s;
}

Vec3 GregoryPatch::normal(double u, double v) const
{
  Vec3 du, dv;
  evaluate(u, v, &du, &dv);
  return normalFrom(du, dv, u, v);
}

Vec3 GregoryPatch::normalFrom(const Vec3& du, const Vec3& dv, double u, double v) const
{
  const Vec3 n = du.cross(dv);
  if (n.norm() > 1e-14 * (du.norm() * dv.norm() + 1e-300))
  {
    return n.normalized();
  }
  // Degenerate (for example a collapsed side): step inside the patch.
  const double e = 1e-7;
  Vec3 iu, iv;
  evaluate(std::min(std::max(u, e), 1.0 - e), std::min(std::max(v, e), 1.0 - e), &iu, &iv);
  return iu.cross(iv).normalized();
}

Vec3 bezier(const std::array<Vec3, 4>& c, double t)
{
  const double s = 1.0 - t;
  return s * s * s * c[0] + 3.0 * t * s * s * c[1] + 3.0 * t * t * s * c[2] + t * t * t * c[3];
}

Vec3 bezierDerivative(const std::array<Vec3, 4>& c, double t)
{
  const double s = 1.0 - t;
  return 3.0 * (s * s * (c[1] - c[0]) + 2.0 * t * s * (c[2] - c[1]) + t * t * (c[3] - c[2]));
}

} // namespace lk
