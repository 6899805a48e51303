#pragma once
/// \file IteratedShuffle.h
/// The one-dimensional Iterated Shuffle Transformation (IST) of wrinkly
/// surfaces (seed 000, Fujimoto and Ohno, section 2.1 and figure 1).
///
/// The paper refers to an earlier paper for the definition; this is the
/// reconstruction used here, chosen to have every property the paper states.
///
/// The axis is cut into base intervals [i, i + 1) (i an integer). Every base
/// interval has the same shuffle count M (the paper's surfaces and its
/// footnote 4 use one count per axis), so each iteration cuts every current
/// sub-interval into n = 2M + 1 pieces, and a point of base interval i is
/// labelled by the base index and its base-n digits,
///     x = i + 0.d1 d2 ... dK (r)          (r: the rest, below n^-K),
/// as in figure 1 (6 -> 60, 61, 62 -> 600, ...). Iteration k (1 <= k <= K)
/// moves pieces among neighbouring intervals of its own level:
///   - k = 1: the n pieces of base interval c go to the base intervals
///     c - M ... c + M, piece j into c + M - j, keeping its slot j (so target
///     interval t holds, in slots 0 ... 2M, pieces of t - M ... t + M:
///     neighbouring intervals are interleaved);
///   - k >= 2: inside every sub-interval of level k - 2, its n children are
///     the neighbouring intervals, taken cyclically: piece j of child c goes
///     to child (c + M - j) mod n, keeping its slot j.
/// Composed, this is the closed form
///     t   = i + M - d1                 (mod N on a cyclic axis)
///     e_k = (d_k - d_(k+1) + M) mod n   for k < K,   e_K = d_K,
///     y   = t + 0.e1 ... eK (r),
/// and its inverse  d_K = e_K,  d_k = (e_k + d_(k+1) - M) mod n,
/// i = t - M + d1. Properties (each is a test):
///   - bijection between the source and target axes for every K (the digit
///     map is invertible, and it is a translation on each of the n^K pieces
///     of a base interval: piecewise);
///   - local: a piece of base interval i lands in base interval t with
///     |t - i| <= M, whatever K;
///   - defined for any K >= 0 (K = 0 is the identity);
///   - local resemblance in space and scale: take any sub-interval W of the
///     target axis at level k < K (k = 0: a base interval) and its n children.
///     The leading digits (source base intervals, written as i - t + M in
///     0 ... 2M) of the n^(K-k-1) pieces under child c + 1 are those under
///     child c shifted by one (mod n): incrementing e_(k+1) increments every
///     d_k, ..., d_1 mod n. This is figure 1's observation that in each of its
///     windows (1), (2), (3) the leading digits of the three parts are shifted
///     by one, and it holds at every K.
/// Axis kinds: a translation axis (open ends) is the infinite axis; a
/// wrinkly surface mirrors positions that leave its finite axis back into it
/// (mirrorInto), which extends the height function evenly beyond the ends.
/// A cyclic axis of N base intervals takes base indices mod N.

#include <cstdint>
#include <vector>

namespace lk
{

enum class ShuffleAxis
{
  Translation,
  Cyclic
};

/// A labelled piece: base interval and its K base-n digits.
struct ShuffleLabel
{
  std::int64_t base = 0;
  std::vector<int> digits;
};

class IteratedShuffle
{
public:
  /// M >= 0, K >= 0 with (2M + 1)^K <= 2^50; a cyclic axis needs
  /// baseIntervals >= 1. Throws std::invalid_argument otherwise.
  IteratedShuffle(int shuffleCount, int iterations, ShuffleAxis axis = ShuffleAxis::Translation,
    int baseIntervals = 0);

  int shuffleCount() const { return M_; }
  int iterations() const { return K_; }
  int pieces() const { return n_; }                  ///< n = 2M + 1
  std::int64_t piecesPerBase() const { return nK_; } ///< n^K
  ShuffleAxis axis() const { return axis_; }

  /// Source label -> target label (F) and back (F^-1).
  ShuffleLabel forward(const ShuffleLabel& source) const;
  ShuffleLabel inverse(const ShuffleLabel& target) const;

  /// F and F^-1 on axis coordinates: translations of the n^K pieces.
  double forward(double x) const;
  double inverse(double y) const;

  /// The label of the level-K piece holding x, and the piece's start.
  ShuffleLabel labelOf(double x) const;
  double startOf(const ShuffleLabel& label) const;

  /// Mirror x into [0, length) (even extension at both ends).
  static double mirrorInto(double x, double length);

private:
  std::int64_t wrap(std::int64_t base) const;

  int M_, K_, n_, N_;
  std::int64_t nK_;
  ShuffleAxis axis_;
};

} // namespace lk
