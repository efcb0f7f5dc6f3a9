#include "engine/sim/broad_phase.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>

namespace baize::engine {
namespace {

// The Bernstein coefficients must exceed this many unit roundoffs of sum |c_k| T^k: their own
// rounding (a few operations per coefficient, a few more per halving) and the root finder's band
// (kPolynomialErrorUnitRoundoffs of the same sum, plus its evaluation's rounding) both lie well
// below it, so the root finder, run instead, would find no root either.
constexpr double kBernsteinMarginRoundoffs = 64;
// Pieces halved at most this deep (2^3 = 8 pieces at most): balls that pass closer than that
// resolves are left to the root finder.
constexpr int kBernsteinMaxHalvings = 3;

// opensThroughout(): the gap's computed value at the horizon must exceed this many times its own
// rounding error bound (the root finder's, kPolynomialErrorUnitRoundoffs unit roundoffs of its
// terms), so that the root finder, evaluating the same polynomial (scaled by a power of two: the
// same relative rounding), sees it clearly positive too: 4 covers the scaling's and the two
// evaluations' differences in the order of rounding.
constexpr double kOpeningEndMarginBounds = 4;
// ... and at least this share of the largest coefficient's magnitude. The root finder scales the
// polynomial by 2^-e (e the largest coefficient's exponent) and counts a value within a fixed
// floor of a few subnormals as zero; a value of at least 2^-900 of the largest coefficient is
// still at least 2^-901 after scaling, far above that floor (a value near it arises only with a
// subnormal horizon).
constexpr double kOpeningEndFloorShare = 0x1p-900;

using Bernstein = std::array<double, 5>;

bool allAbove(const Bernstein& b, double margin) {
  return std::all_of(b.begin(), b.end(), [margin](double x) { return x > margin; });
}

// Whether the piece with Bernstein coefficients b stays above margin, halving it (de Casteljau) at
// most `halvings` more times.
bool pieceStaysAbove(const Bernstein& b, double margin, int halvings) {
  if (!(b[0] > margin) || !(b[4] > margin)) return false;  // an end is not: no proof possible
  if (allAbove(b, margin)) return true;
  if (halvings == 0) return false;
  Bernstein left, right, row = b;
  for (int level = 0; level < 5; ++level) {
    left[level] = row[0];
    right[4 - level] = row[4 - level];
    for (int k = 0; k < 4 - level; ++k) row[k] = 0.5 * (row[k] + row[k + 1]);
  }
  return pieceStaysAbove(left, margin, halvings - 1) &&
         pieceStaysAbove(right, margin, halvings - 1);
}

}  // namespace

bool bernsteinStaysPositive(const physics::PolynomialCoefficients& p, double horizon) {
  // a_k = c_k T^k: p on [0, 1] in s = t / T.
  std::array<double, 5> a;
  double power = 1, magnitude = 0;
  for (int k = 0; k < 5; ++k) {
    a[k] = p[k] * power;
    magnitude += std::abs(a[k]);
    power *= horizon;
  }
  if (!std::isfinite(magnitude)) return false;
  // b_i = sum_{k <= i} C(i, k) / C(4, k) a_k.
  const Bernstein b = {a[0], a[0] + a[1] / 4, a[0] + a[1] / 2 + a[2] / 6,
                       a[0] + 3 * a[1] / 4 + a[2] / 2 + a[3] / 4, a[0] + a[1] + a[2] + a[3] + a[4]};
  return pieceStaysAbove(b, kBernsteinMarginRoundoffs * 0x1p-53 * magnitude,
                         kBernsteinMaxHalvings);
}

bool opensThroughout(const physics::PolynomialCoefficients& p, double horizon) {
  if (!(horizon > 0) || !std::isfinite(horizon)) return false;
  // The derivative's coefficients as the root finder forms them (k c_k; its scaling of p by a power
  // of two is exact), proved positive with the same margin over its rounding band as a gap.
  const physics::PolynomialCoefficients slope = {p[1], 2 * p[2], 3 * p[3], 4 * p[4], 0};
  if (!bernsteinStaysPositive(slope, horizon)) return false;
  const physics::PolynomialValue end = physics::evaluatePolynomialWithErrorBound(p, horizon);
  double largest = 0;
  for (double c : p) largest = std::max(largest, std::abs(c));
  return end.value > kOpeningEndMarginBounds * end.error_bound &&
         end.value > kOpeningEndFloorShare * largest;
}

RestingGrid::RestingGrid(const std::vector<int>& indices,
                         const std::vector<physics::BallState>& balls, double R) {
  if (indices.empty()) return;
  Eigen::AlignedBox2d extent;
  for (int i : indices) extent.extend(balls[i].position);
  origin_m_ = extent.min();
  const Eigen::Vector2d size = extent.sizes();
  const double per_cell = static_cast<double>(indices.size()) * kGridCellsPerBall;
  cell_m_ = std::max(
      {kGridCellRadii * R, std::sqrt(size.x() * size.y() / per_cell), size.maxCoeff() / per_cell});
  columns_ = cellOf(extent.max().x(), origin_m_.x(), kMaxCells) + 1;
  rows_ = cellOf(extent.max().y(), origin_m_.y(), kMaxCells) + 1;
  // Counting sort of the balls by cell: cell c holds members_[first_[c]] to
  // members_[first_[c+1]).
  std::vector<int> cell(indices.size());
  first_.assign(static_cast<std::size_t>(columns_) * rows_ + 1, 0);
  for (std::size_t k = 0; k < indices.size(); ++k) {
    const Eigen::Vector2d& q = balls[indices[k]].position;
    cell[k] =
        cellOf(q.y(), origin_m_.y(), rows_) * columns_ + cellOf(q.x(), origin_m_.x(), columns_);
    ++first_[cell[k] + 1];
  }
  for (std::size_t c = 1; c < first_.size(); ++c) first_[c] += first_[c - 1];
  members_.resize(indices.size());
  std::vector<int> filled(first_.begin(), first_.end() - 1);
  for (std::size_t k = 0; k < indices.size(); ++k) members_[filled[cell[k]]++] = indices[k];
}

}  // namespace baize::engine
