// The broad phase of the event loop: cheap bounds that keep pairs, cushions, jaws and pockets
// that cannot meet away from the root finder. Boxes swept by balls along their paths, a grid of the
// balls resting at the start, and bounds on gap polynomials. Every bound errs on the side of
// solving: it may let a pair through that never meets, never drop one that does.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "physics/cloth_motion.h"
#include "physics/polynomial_roots.h"

namespace baize::engine {

// Boxes and distance bounds are widened by this, m, so that rounding in the path's extremes cannot
// drop a contact (positions are ~1 m, rounded to ~1e-16 m; contacts are located to ~1e-14 m).
constexpr double kBoxMargin_m = 1e-9;

// |c + l t + q t^2 - centre|^2 - distance^2 as coefficients in t.
inline physics::PolynomialCoefficients squaredGap(const physics::PositionQuadratic& path,
                                                  const Eigen::Vector2d& centre,
                                                  const Eigen::Vector2d& linear_other,
                                                  const Eigen::Vector2d& quadratic_other,
                                                  double distance) {
  const Eigen::Vector2d c = path.constant_m - centre;
  const Eigen::Vector2d l = path.linear_mps - linear_other;
  const Eigen::Vector2d q = path.quadratic_mps2 - quadratic_other;
  return {c.dot(c) - distance * distance, 2 * c.dot(l), l.dot(l) + 2 * c.dot(q), 2 * l.dot(q),
          q.dot(q)};
}

// A quadratic's lowest value on an interval counts as positive when it exceeds this many unit
// roundoffs of the magnitudes it was computed from (a handful of operations, with room).
constexpr double kQuadraticBoundRoundoffs = 16;

// The lowest value of c0 + c1 t + c2 t^2 on [0, T] (T finite), and the size of the terms it came
// from (for its rounding).
struct LowestValue {
  double value, magnitude;
};
inline LowestValue quadraticLowestValue(double c0, double c1, double c2, double horizon) {
  const double vertex = c2 > 0 ? -c1 / (2 * c2) : -1;  // where a convex quadratic is lowest
  if (vertex > 0 && vertex < horizon) {
    const double drop = c1 * c1 / (4 * c2);
    return {c0 - drop, std::abs(c0) + drop};
  }
  return {std::min(c0, c0 + (c1 + c2 * horizon) * horizon),
          std::abs(c0) + (std::abs(c1) + std::abs(c2) * horizon) * horizon};
}

// Whether a point moving as c + l t + q t^2 relative to a centre stays farther than `distance`
// from it over [0, horizon]: its distance is at least its projection on the starting direction,
// a quadratic whose lowest value is exact. (Balls moving apart or passing wide, a ball heading away
// from a pocket: no quartic to solve.)
inline bool staysFarther(const Eigen::Vector2d& c, const Eigen::Vector2d& l,
                         const Eigen::Vector2d& q, double distance, double horizon) {
  const double start = c.norm();
  if (!(start > distance) || !std::isfinite(horizon)) return false;
  const Eigen::Vector2d direction = c / start;
  const LowestValue lowest =
      quadraticLowestValue(start, l.dot(direction), q.dot(direction), horizon);
  return lowest.value > distance + kBoxMargin_m;
}

// Whether quartic p stays positive on [0, horizon] (finite) by its Bernstein coefficients there:
// p is a weighted mean of them on each piece, so all of them positive (by a margin that covers
// their rounding and the root finder's own rounding band) proves it. Pieces are halved while a
// coefficient is not, up to kBernsteinMaxHalvings times.
bool bernsteinStaysPositive(const physics::PolynomialCoefficients& p, double horizon);

// Whether gap polynomial p only opens over [0, horizon] (finite): its derivative stays positive
// there by its Bernstein coefficients, and p ends clearly positive. The root finder then finds no
// critical point inside and no closing root, whatever p is at the start (a contact that was just
// resolved and separates: p starts within rounding of zero, so staysApart() cannot say).
bool opensThroughout(const physics::PolynomialCoefficients& p, double horizon);

// Whether gap polynomial p stays positive on [0, horizon], so that the root finder need not run: a
// quadratic (a straight cushion) by its lowest value there, exactly; a quartic by the bound
// p(t) >= c0 - sum |c_k| T^k, then by its Bernstein coefficients.
inline bool staysApart(const physics::PolynomialCoefficients& p, double horizon) {
  if (!(p[0] > 0) || !std::isfinite(horizon)) return false;
  if (p[3] == 0 && p[4] == 0) {
    const LowestValue lowest = quadraticLowestValue(p[0], p[1], p[2], horizon);
    return lowest.value > kQuadraticBoundRoundoffs * 0x1p-53 * lowest.magnitude;
  }
  double bound = 0, power = 1;
  for (int k = 1; k < 5; ++k) {
    power *= horizon;
    bound += std::abs(p[k]) * power;
  }
  return p[0] - bound > 0 || bernsteinStaysPositive(p, horizon);
}

// Whether c0 + c1 t + c2 t^2 (a straight cushion's gap, m) stays above kBoxMargin_m on [0, T]: then
// its first root, if any, comes after T (the margin is far above the rounding of either).
inline bool quadraticStaysAbove(const physics::PolynomialCoefficients& p, double T) {
  if (!std::isfinite(T)) return false;
  return quadraticLowestValue(p[0], p[1], p[2], T).value > kBoxMargin_m;
}

// An axis-aligned box in the table plane, m: the broad phase that keeps pairs and cushions that
// cannot meet away from the root finder.
struct Box {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d hi = Eigen::Vector2d::Constant(-std::numeric_limits<double>::infinity());
  static Box around(const Eigen::Vector2d& centre, double radius) {
    return {centre.array() - radius, centre.array() + radius};
  }
  static Box spanning(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return {a.cwiseMin(b), a.cwiseMax(b)};
  }
  Box inflated(double margin) const { return {lo.array() - margin, hi.array() + margin}; }
  bool overlaps(const Box& o) const {
    return lo.x() <= o.hi.x() && o.lo.x() <= hi.x() && lo.y() <= o.hi.y() && o.lo.y() <= hi.y();
  }
};

// The box a ball of radius R sweeps along `path` over [0, duration] (everything, if the duration
// is not finite).
inline Box sweptBox(const physics::PositionQuadratic& path, double duration, double R) {
  if (!std::isfinite(duration))
    return {Eigen::Vector2d::Constant(-std::numeric_limits<double>::infinity()),
            Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity())};
  Box box = Box::spanning(path.constant_m, path.at(duration));
  for (int axis = 0; axis < 2; ++axis) {
    const double q = path.quadratic_mps2[axis];
    if (q == 0) continue;
    const double turn = -path.linear_mps[axis] / (2 * q);  // where this coordinate turns back
    if (turn > 0 && turn < duration) {
      const double extreme = path.at(turn)[axis];
      box.lo[axis] = std::min(box.lo[axis], extreme);
      box.hi[axis] = std::max(box.hi[axis], extreme);
    }
  }
  return box.inflated(R + kBoxMargin_m);
}

// The grid's cells are this many ball radii wide at least: a box swept in a short step covers a
// few cells, and a cell holds a few resting balls at most.
constexpr double kGridCellRadii = 4;
// The grid has at most about this many cells per ball (its cells widen on a sparse, wide spread of
// balls), so that it costs O(balls) to build.
constexpr double kGridCellsPerBall = 2;

// The balls at rest when the shot starts (numbers `indices` of `balls`), by the cells of a uniform
// grid of their centres: a moving ball looks only in the cells its swept box reaches instead of at
// every ball, so a crowd of resting balls costs little per event. Built once per shot: a ball that
// moves later is left for the caller to skip.
class RestingGrid {
 public:
  RestingGrid() = default;  // holds no ball
  RestingGrid(const std::vector<int>& indices, const std::vector<physics::BallState>& balls,
              double R);

  // Calls visit(i) once for every ball in the grid whose centre may lie within `reach` (m) of
  // `box` (and for some farther ones).
  template <class Visit>
  void forEachNear(const Box& box, double reach, Visit visit) const {
    if (members_.empty()) return;
    const int x0 = cellOf(box.lo.x() - reach, origin_m_.x(), columns_);
    const int x1 = cellOf(box.hi.x() + reach, origin_m_.x(), columns_);
    const int y0 = cellOf(box.lo.y() - reach, origin_m_.y(), rows_);
    const int y1 = cellOf(box.hi.y() + reach, origin_m_.y(), rows_);
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const int c = y * columns_ + x;
        for (int k = first_[c]; k < first_[c + 1]; ++k) visit(members_[k]);
      }
    }
  }

 private:
  static constexpr int kMaxCells = 1 << 20;  // per axis; far above what kGridCellsPerBall allows
  // The cell along one axis holding coordinate q, clamped to [0, count): a box reaching beyond the
  // grid (or not finite) covers the cells at its edge.
  int cellOf(double q, double origin, int count) const {
    const double c = (q - origin) / cell_m_;
    if (!(c >= 1)) return 0;
    if (c >= count - 1) return count - 1;
    return static_cast<int>(c);  // truncation: the floor, c being >= 1 here
  }

  Eigen::Vector2d origin_m_ = Eigen::Vector2d::Zero();
  double cell_m_ = 1;
  int columns_ = 0, rows_ = 0;
  std::vector<int> first_;    // per cell, then one past the last: where its balls start in members_
  std::vector<int> members_;  // ball numbers, cell by cell
};

}  // namespace baize::engine
