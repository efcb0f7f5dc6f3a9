#include "engine/sim/shot_simulator.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>

#include "engine/sim/contact_geometry.h"
#include "engine/sim/cushion_solve_ahead.h"
#include "physics/polynomial_roots.h"
#include "physics/value_text.h"

namespace baize::engine {
namespace {

using physics::BallState;
using physics::PolynomialCoefficients;

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Balls may start this much closer than touching (m) and still count as touching: positions written
// in a scene file or placed by a rack round to about this.
constexpr double kContactSlack_m = 1e-9;
// Boxes and distance bounds are widened by this, m, so that rounding in the path's extremes cannot
// drop a contact (positions are ~1 m, rounded to ~1e-16 m; contacts are located to ~1e-14 m).
constexpr double kBoxMargin_m = 1e-9;
// Sustained contact: a ball pressed into another ball or a cushion by cloth friction (spin driving
// it on, or the ball ahead slowing faster) makes a Zeno sequence of ever smaller bounces that the
// cloth damps out, ending in a contact that lasts. The event loop keeps such a contact as a steady
// train of small bounces instead: a pressed contact leaves at this separation speed at least, m/s,
// the energy for it taken from the balls' spin (the source that presses them). The impulses then
// average to the pressing force of the lasting contact, the relative speed ripples by at most this
// much and the gap by this^2 / (2 a) (0.25 um at a = 2 m/s^2), and a push of a second costs about
// a thousand events. Invisible at table scale, well above rounding.
constexpr double kSustainedContactSpeed_mps = 1e-3;
// Fraction of the energy budget left unspent by that release, so that rounding in the energy sums
// cannot make the balls' energy grow.
constexpr double kEnergyBudgetMargin = 1e-9;
// Events a result has room for from the start: a random single shot has about eight.
constexpr std::size_t kEventsReserved = 16;

struct Candidate {
  double dt_s = kInfinity;  // from now
  EventKind kind = EventKind::StateChange;
  int ball = -1, other = -1, index = -1;

  // Earliest first; ties broken by kind, then by the balls' and the cushion's or pocket's numbers,
  // so the same input always resolves in the same order.
  bool operator<(const Candidate& c) const {
    return std::make_tuple(dt_s, static_cast<int>(kind), ball, other, index) <
           std::make_tuple(c.dt_s, static_cast<int>(c.kind), c.ball, c.other, c.index);
  }
  bool sameContact(const Candidate& c) const {
    return kind == c.kind && ball == c.ball && other == c.other && index == c.index;
  }
};

bool moving(const physics::ClothParams& cloth, const BallState& ball) {
  const physics::MotionState state = physics::motionState(cloth, ball);
  return state == physics::MotionState::Sliding || state == physics::MotionState::Rolling;
}

// |c + l t + q t^2 - centre|^2 - distance^2 as coefficients in t.
PolynomialCoefficients squaredGap(const physics::PositionQuadratic& path,
                                  const Eigen::Vector2d& centre,
                                  const Eigen::Vector2d& linear_other,
                                  const Eigen::Vector2d& quadratic_other, double distance) {
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
LowestValue quadraticLowestValue(double c0, double c1, double c2, double horizon) {
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
bool staysFarther(const Eigen::Vector2d& c, const Eigen::Vector2d& l, const Eigen::Vector2d& q,
                  double distance, double horizon) {
  const double start = c.norm();
  if (!(start > distance) || !std::isfinite(horizon)) return false;
  const Eigen::Vector2d direction = c / start;
  const LowestValue lowest =
      quadraticLowestValue(start, l.dot(direction), q.dot(direction), horizon);
  return lowest.value > distance + kBoxMargin_m;
}

// Whether gap polynomial p stays positive on [0, horizon], so that the root finder need not run: a
// quadratic (a straight cushion) by its lowest value there, exactly; a quartic by the bound
// p(t) >= c0 - sum |c_k| T^k.
bool staysApart(const PolynomialCoefficients& p, double horizon) {
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
  return p[0] - bound > 0;
}

// Raises the separation speed of a pressed contact towards kSustainedContactSpeed_mps (see there)
// by a normal impulse, paying the energy it adds out of the balls' spin and out of what the impact
// itself dissipated (`energy_before_J` is the balls' kinetic energy before it): as far as that
// budget reaches, so energy never grows. `normal` points from `first` to `second`; `second` is null
// for a cushion (infinite mass; the normal then points away from it, into the table).
void releasePressedContact(const physics::CushionParams& ball, double energy_before_J,
                           const Eigen::Vector3d& normal, physics::BallVelocity* first,
                           physics::BallVelocity* second) {
  const double separation = second ? (second->v - first->v).dot(normal) : first->v.dot(normal);
  if (separation >= kSustainedContactSpeed_mps) return;
  auto spinEnergy = [&](const physics::BallVelocity& b) {
    return physics::kineticEnergy(ball, {Eigen::Vector3d::Zero(), b.w});
  };
  const double energy =
      physics::kineticEnergy(ball, *first) + (second ? physics::kineticEnergy(ball, *second) : 0);
  const double spin = spinEnergy(*first) + (second ? spinEnergy(*second) : 0);
  // Spin paid out is spin * (1 - scale^2); keep a rounding margin so energy cannot grow.
  const double budget = (spin + energy_before_J - energy) * (1 - kEnergyBudgetMargin);
  if (!(budget > 0)) return;
  // The kinetic energy the boost b adds: m/4 (2 b s + b^2) for two balls of mass m (each takes
  // half), m/2 (2 b s + b^2) for one ball off a cushion; the largest b within budget solves the
  // quadratic.
  const double effective_mass = second ? ball.mass_kg / 2 : ball.mass_kg;
  const double affordable =
      -separation + std::sqrt(separation * separation + 2 * budget / effective_mass);
  const double boost = std::min(kSustainedContactSpeed_mps - separation, affordable);
  if (!(boost > 0)) return;
  if (second) {
    first->v -= 0.5 * boost * normal;
    second->v += 0.5 * boost * normal;
  } else {
    first->v += boost * normal;
  }
  const double excess = physics::kineticEnergy(ball, *first) +
                        (second ? physics::kineticEnergy(ball, *second) : 0) - energy_before_J;
  if (excess <= 0) return;
  const double scale = std::sqrt(std::max(0.0, 1 - excess / spin));
  first->w *= scale;
  if (second) second->w *= scale;
}

// An axis-aligned box in the table plane, m: the broad phase that keeps pairs and cushions that
// cannot meet away from the root finder.
struct Box {
  Eigen::Vector2d lo = Eigen::Vector2d::Constant(kInfinity);
  Eigen::Vector2d hi = Eigen::Vector2d::Constant(-kInfinity);
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
Box sweptBox(const physics::PositionQuadratic& path, double duration, double R) {
  if (!std::isfinite(duration))
    return {Eigen::Vector2d::Constant(-kInfinity), Eigen::Vector2d::Constant(kInfinity)};
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
  RestingGrid(const std::vector<int>& indices, const std::vector<BallState>& balls, double R) {
    if (indices.empty()) return;
    Eigen::AlignedBox2d extent;
    for (int i : indices) extent.extend(balls[i].position);
    origin_m_ = extent.min();
    const Eigen::Vector2d size = extent.sizes();
    const double per_cell = static_cast<double>(indices.size()) * kGridCellsPerBall;
    cell_m_ = std::max({kGridCellRadii * R, std::sqrt(size.x() * size.y() / per_cell),
                        size.maxCoeff() / per_cell});
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

// A convex polygon of at most kMaxClippedCorners corners, m: the box a half-strip is clipped from.
// A box (4 corners) cut by three half-planes has at most 4 + 3 = 7.
constexpr int kMaxClippedCorners = 8;
struct ConvexPolygon {
  std::array<Eigen::Vector2d, kMaxClippedCorners> corners;
  int size = 0;
};

// The part of `polygon` where a.q <= b (Sutherland-Hodgman against one half-plane).
ConvexPolygon clipped(const ConvexPolygon& polygon, const Eigen::Vector2d& a, double b) {
  ConvexPolygon out;
  for (int k = 0; k < polygon.size; ++k) {
    const Eigen::Vector2d& p = polygon.corners[k];
    const Eigen::Vector2d& q = polygon.corners[(k + 1) % polygon.size];
    const double fp = a.dot(p) - b, fq = a.dot(q) - b;
    if (fp <= 0) out.corners[out.size++] = p;
    if ((fp < 0 && fq > 0) || (fp > 0 && fq < 0))
      out.corners[out.size++] = p + (fp / (fp - fq)) * (q - p);
  }
  return out;
}

// The safe interior below is built this far inside the cushion noses and checked with half this
// margin to spare, m: far above the rounding of the checks' dot products (positions ~1 m, ~1e-16
// m), far below anything that matters for which balls it admits.
constexpr double kSafeInteriorMargin_m = 1e-6;
// A cushion normal counts as along an axis when its other component is below this (unit vector;
// the shipped tables' rail normals are axis-aligned to rounding).
constexpr double kAxisAlignedNormal = 1e-9;
// Below this many balls the safe interior costs more than it saves (it costs about as much as the
// full cushion and jaw checks of some 8 balls on a pool table, by instruction counts).
constexpr std::size_t kSafeInteriorMinBalls = 8;

// A box of ball centres that no cushion or jaw check can reject, so that balls inside it skip those
// checks (a crowded table then costs little per ball); empty when none is found. Its sides are the
// axis-aligned cushion noses moved R inwards, within the table's extent. Every cushion's and jaw's
// rejection region (a centre nearer than R in front of or anywhere behind a cushion, beside it; a
// centre within the jaw's radius + R) is then checked against the whole box, grown by a margin,
// and any that reaches into the box empties it.
Eigen::AlignedBox2d safeInterior(const TableGeometry& table, double R,
                                 const Eigen::AlignedBox2d& extent) {
  Eigen::AlignedBox2d box = extent;
  const double inset = R + kSafeInteriorMargin_m;
  for (const CushionSegment& c : table.cushions) {
    for (int axis = 0; axis < 2; ++axis) {
      if (!(std::abs(c.inward_normal[1 - axis]) < kAxisAlignedNormal)) continue;
      if (c.inward_normal[axis] > 0) {
        box.min()[axis] =
            std::max(box.min()[axis], std::max(c.start_m[axis], c.end_m[axis]) + inset);
      } else {
        box.max()[axis] =
            std::min(box.max()[axis], std::min(c.start_m[axis], c.end_m[axis]) - inset);
      }
    }
  }
  // Non-finite geometry (which validation lets through) would make the clipping below meaningless.
  if (box.isEmpty() || !box.min().allFinite() || !box.max().allFinite())
    return Eigen::AlignedBox2d();
  const double spare = kSafeInteriorMargin_m / 2;
  for (const JawArc& jaw : table.jaws) {
    const Eigen::Vector2d nearest = jaw.centre_m.cwiseMax(box.min()).cwiseMin(box.max());
    const double clear = jaw.radius_m + R + spare;
    if (!((nearest - jaw.centre_m).squaredNorm() >= clear * clear)) return Eigen::AlignedBox2d();
  }
  ConvexPolygon corners;
  for (auto corner : {Eigen::AlignedBox2d::BottomLeft, Eigen::AlignedBox2d::BottomRight,
                      Eigen::AlignedBox2d::TopRight, Eigen::AlignedBox2d::TopLeft})
    corners.corners[corners.size++] = box.corner(corner);
  for (const CushionSegment& c : table.cushions) {
    // Rejected beside the cushion (0 <= s <= 1 along it) at a distance below R in front of it.
    if (!c.start_m.allFinite() || !c.end_m.allFinite()) return Eigen::AlignedBox2d();
    const Eigen::Vector2d along = c.end_m - c.start_m;
    const double length = along.norm();
    // (The box usually lies wholly in front of a cushion: the first cut then leaves nothing.)
    ConvexPolygon reach =
        clipped(corners, c.inward_normal, c.inward_normal.dot(c.start_m) + R + spare);
    if (reach.size > 0) reach = clipped(reach, -along, -along.dot(c.start_m) + spare * length);
    if (reach.size > 0)
      reach = clipped(reach, along, along.dot(c.start_m) + along.squaredNorm() + spare * length);
    if (reach.size > 0) return Eigen::AlignedBox2d();
  }
  return box;
}

// A ball in messages: by its id when the caller gave ids, else by its number.
std::string ballName(const std::vector<std::string>& ids, std::size_t i) {
  return ids.empty() ? "ball " + std::to_string(i) : "ball '" + ids[i] + "'";
}

// The runtime guard against balls leaving the table (BallLeftTableError). A ball on the table
// keeps its centre R from the rails and enters a capture circle before the line closing a
// pocket's opening, so no tolerance is needed at the outline.
void requireOnTable(const TableGeometry& table, const Event& event, int ball, bool pocketed,
                    const BallState& state, const std::vector<std::string>& ids) {
  if (pocketed || table.rail_box.contains(state.position) ||
      insideOutline(table.outline, state.position)) {
    return;
  }
  throw BallLeftTableError(
      ballName(ids, static_cast<std::size_t>(ball)) + " left the table: at t = " +
      physics::valueText(event.time_s) + " s (a " + eventKindName(event.kind) +
      " event) its centre [" + physics::valueText(state.position.x()) + ", " +
      physics::valueText(state.position.y()) +
      "] m is outside the table's cushion outline and not in a pocket (a capture circle that "
      "does not cover its pocket's opening lets balls through)");
}

}  // namespace

void validateSimulationInput(const SimulationParams& p, const TableGeometry& table,
                             const std::vector<BallState>& balls,
                             const std::vector<std::string>& ball_ids) {
  if (!ball_ids.empty() && ball_ids.size() != balls.size()) {
    physics::rejectValue("number of ball ids", static_cast<double>(ball_ids.size()),
                         "it must be 0 or the number of balls, " + std::to_string(balls.size()));
  }
  physics::validateClothParams(p.cloth);
  physics::validateCushionParams(p.cushion);
  physics::validateBallBallParams(p.ball_ball);
  validateCushionContactParams(p);
  const double R = p.cushion.radius_m;
  if (p.cloth.radius_m != R || p.ball_ball.radius_m != R) {
    physics::rejectValue("ball radius of the cloth and ball-ball parameters (m)", p.cloth.radius_m,
                         "it must equal the cushion parameters' radius " + physics::valueText(R));
  }
  if (p.ball_ball.mass1_kg != p.cushion.mass_kg || p.ball_ball.mass2_kg != p.cushion.mass_kg) {
    physics::rejectValue(
        "ball mass of the ball-ball parameters (kg)", p.ball_ball.mass1_kg,
        "it must equal the cushion parameters' mass " + physics::valueText(p.cushion.mass_kg));
  }
  if (!(p.max_events > 0))
    physics::rejectValue("max_events", static_cast<double>(p.max_events), "it must be > 0");
  for (const CushionSegment& c : table.cushions) {
    if (!(std::abs(c.inward_normal.norm() - 1) < 1e-9) || !((c.end_m - c.start_m).norm() > 0)) {
      throw std::invalid_argument(
          "cushion segment: it needs a unit inward normal and two distinct ends");
    }
  }
  for (std::size_t k = 0; k < table.jaws.size(); ++k) {
    const JawArc& jaw = table.jaws[k];
    if (!(jaw.radius_m > 0) || !(jaw.end_angle_rad >= jaw.start_angle_rad) ||
        !(jaw.end_angle_rad - jaw.start_angle_rad <= 2 * M_PI)) {
      physics::rejectValue("jaw " + std::to_string(k) + " radius (m)", jaw.radius_m,
                           "a jaw needs a radius > 0 and an angle range of at most one turn");
    }
  }
  auto who = [&](std::size_t i) { return ballName(ball_ids, i); };
  for (std::size_t i = 0; i < balls.size(); ++i) {
    try {
      physics::validateBallState(balls[i]);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(who(i) + ": " + e.what());
    }
    // Speeds and spins within the bounds every impact model takes (cushion_model.h); far beyond
    // them the arithmetic is not sound (w_z^2 overflows above about 1e154 rad/s). Found by
    // fuzzing: a ball touching a cushion with w_z = -5.7e250 rad/s was accepted and left the table.
    static const char* const axes[] = {"x", "y", "z"};
    for (int c = 0; c < 3; ++c) {
      if (!(std::abs(balls[i].velocity[c]) <= physics::kMaxBallSpeed_mps)) {
        physics::rejectValue(
            who(i) + " velocity v_" + axes[c] + " (m/s)", balls[i].velocity[c],
            "it must be of magnitude at most " + physics::valueText(physics::kMaxBallSpeed_mps));
      }
      if (!(std::abs(balls[i].angular_velocity[c]) <= physics::kMaxBallSpin_radps)) {
        physics::rejectValue(
            who(i) + " angular velocity w_" + axes[c] + " (rad/s)", balls[i].angular_velocity[c],
            "it must be of magnitude at most " + physics::valueText(physics::kMaxBallSpin_radps));
      }
    }
  }
  // Overlaps by a sweep along x: only balls less than 2R apart in x can overlap (n log n, so that
  // a crowded table costs little).
  struct Centre {
    double x, y;
    std::size_t ball;
  };
  std::vector<Centre> by_x(balls.size());  // by x, then by ball
  for (std::size_t i = 0; i < balls.size(); ++i)
    by_x[i] = {balls[i].position.x(), balls[i].position.y(), i};
  std::sort(by_x.begin(), by_x.end(), [](const Centre& a, const Centre& b) {
    return a.x < b.x || (a.x == b.x && a.ball < b.ball);
  });
  for (std::size_t m = 0; m < by_x.size(); ++m) {
    for (std::size_t k = m + 1; k < by_x.size() && by_x[k].x - by_x[m].x < 2 * R; ++k) {
      // Balls 2R apart or more in y do not overlap: their distance is at least that (to a rounding
      // far below kContactSlack_m), so the square root is not needed.
      if (std::abs(by_x[k].y - by_x[m].y) >= 2 * R) continue;
      const std::size_t i = std::max(by_x[m].ball, by_x[k].ball),
                        j = std::min(by_x[m].ball, by_x[k].ball);
      const double gap = (balls[i].position - balls[j].position).norm() - 2 * R;
      if (gap < -kContactSlack_m) {
        physics::rejectValue(who(i) + " overlaps " + who(j) + ": their gap (m)",
                             gap, "balls may touch but not overlap (gap >= 0)");
      }
    }
  }
  // A table with cushions encloses its balls: a centre outside the box of its cushion ends, jaws
  // and capture circles is off the table even where no cushion lies across its normal (found by
  // fuzzing: a ball at x = 1e306 m was accepted).
  Eigen::AlignedBox2d extent;
  for (const CushionSegment& c : table.cushions) extent.extend(c.start_m).extend(c.end_m);
  auto extendByCircle = [&](const Eigen::Vector2d& centre_m, double radius_m) {
    extent.extend(Eigen::Vector2d(centre_m.array() - radius_m));
    extent.extend(Eigen::Vector2d(centre_m.array() + radius_m));
  };
  for (const JawArc& jaw : table.jaws) extendByCircle(jaw.centre_m, jaw.radius_m);
  for (const Circle& pocket : table.pockets) extendByCircle(pocket.centre_m, pocket.radius_m);
  const Eigen::AlignedBox2d safe = !table.cushions.empty() && balls.size() >= kSafeInteriorMinBalls
                                       ? safeInterior(table, R, extent)
                                       : Eigen::AlignedBox2d();
  for (std::size_t i = 0; i < balls.size(); ++i) {
    if (!table.cushions.empty() && !extent.contains(balls[i].position)) {
      const Eigen::Vector2d& q = balls[i].position;
      const int axis = q.x() < extent.min().x() || q.x() > extent.max().x() ? 0 : 1;
      physics::rejectValue(who(i) + " is off the table: its " + (axis == 0 ? "x" : "y") + " (m)",
                           q[axis],
                           "it must lie within [" + physics::valueText(extent.min()[axis]) + ", " +
                               physics::valueText(extent.max()[axis]) + "], the table's extent");
    }
    if (safe.contains(balls[i].position)) continue;  // no cushion or jaw reaches it
    for (std::size_t k = 0; k < table.jaws.size(); ++k) {
      const JawArc& jaw = table.jaws[k];
      const double reach = jaw.radius_m + R - kContactSlack_m;
      if ((balls[i].position - jaw.centre_m).squaredNorm() >= reach * reach) continue;
      const double distance = (balls[i].position - jaw.centre_m).norm();
      if (distance < reach && onJawArc(jaw, balls[i].position)) {
        physics::rejectValue(who(i) + " is inside jaw " + std::to_string(k) +
                                 ": its centre's distance from the jaw's centre (m)",
                             distance, "it must be at least the jaw's radius plus the ball's");
      }
    }
    for (std::size_t k = 0; k < table.cushions.size(); ++k) {
      const CushionSegment& c = table.cushions[k];
      const double distance = c.inward_normal.dot(balls[i].position - c.start_m);
      if (distance < R - kContactSlack_m && besideSegment(c, balls[i].position)) {
        physics::rejectValue(who(i) + " is beyond cushion " + std::to_string(k) +
                                 ": its centre's distance from it (m)",
                             distance, "it must be at least the radius " + physics::valueText(R));
      }
    }
  }
}

Eigen::Vector2d contactNormal(const TableGeometry& table, EventKind kind, int index,
                              const Eigen::Vector2d& position) {
  if (kind == EventKind::Cushion) return table.cushions[index].inward_normal;
  return (position - table.jaws[index].centre_m).normalized();
}

physics::BallState sampleTrajectory(const physics::ClothParams& cloth, const Trajectory& trajectory,
                                    double t_s) {
  if (trajectory.empty()) throw std::invalid_argument("sampleTrajectory: the trajectory is empty");
  if (!(t_s >= 0) || !std::isfinite(t_s))
    physics::rejectValue("sample time (s)", t_s, "it must be finite and >= 0");
  auto piece =
      std::upper_bound(trajectory.begin(), trajectory.end(), t_s,
                       [](double t, const TrajectoryPiece& q) { return t < q.start_time_s; });
  --piece;  // the last piece starting at or before t_s (the first starts at 0)
  if (piece->pocketed) return piece->state;
  return physics::advance(cloth, piece->state, t_s - piece->start_time_s);
}

SimulationParams poolSimulationParams() {
  SimulationParams p;
  p.cushion.mass_kg = 0.17;
  p.cushion.radius_m = 0.028575;
  p.cushion.contact_height_m = 0.635 * 2 * p.cushion.radius_m;
  p.cushion.cloth_friction = p.cloth.sliding_friction;
  return p;
}

const char* eventKindName(EventKind kind) {
  switch (kind) {
    case EventKind::StateChange:
      return "state change";
    case EventKind::BallBall:
      return "ball-ball";
    case EventKind::Cushion:
      return "cushion";
    case EventKind::Jaw:
      return "jaw";
    case EventKind::Pocket:
      return "pocket";
  }
  return "?";
}

SimulationResult simulate(const SimulationParams& p, const TableGeometry& table,
                          const std::vector<BallState>& input,
                          const std::vector<std::string>& ball_ids) {
  validateSimulationInput(p, table, input, ball_ids);
  const double R = p.cushion.radius_m;
  SimulationResult result;
  // Room for a typical single shot's events at once (grown one by one, their reallocations were
  // about a tenth of a random shot's allocations).
  result.events.reserve(kEventsReserved);
  const int n = static_cast<int>(input.size());
  if (p.record_trajectories) {
    result.trajectories.resize(n);
    for (int i = 0; i < n; ++i) result.trajectories[i].push_back({0, input[i], false});
  }

  // Each ball's state is kept at its own reference time and moved on only when an event involves
  // it: a ball nothing happens to costs nothing per event. Its path, the time its motion state
  // changes and the box it sweeps until then are computed once per state.
  struct Ball {
    BallState state;
    double reference_time_s = 0;
    double change_dt_s = kInfinity;   // from the reference time to its next state change
    physics::PositionQuadratic path;  // from the reference time
    bool moves = false;               // sliding or rolling: its centre moves
    bool pocketed = false;
    int pocket = -1;
    // Until when its path holds for certain (its next own event: a state change, cushion, jaw or
    // pocket; pairs are predicted no further) and the box it sweeps (inflated by R) until then.
    double valid_until_s = kInfinity;
    Box box;
  };
  std::vector<Ball> balls(n);
  std::vector<char> starts_at_rest(n, 0);  // no velocity and no spin at all at the start
  auto settle = [&](int i, double time_s) {
    Ball& b = balls[i];
    b.reference_time_s = time_s;
    b.change_dt_s = physics::timeToStateChange(p.cloth, b.state);
    b.path = physics::positionQuadratic(p.cloth, b.state);
    b.moves = moving(p.cloth, b.state);
    b.box = b.moves ? sweptBox(b.path, b.change_dt_s, R) : Box::around(b.state.position, R);
  };
  for (int i = 0; i < n; ++i) {
    Ball& b = balls[i];
    b.state = input[i];
    // A ball with no velocity and no spin at all is stationary, never changes state and stays
    // where it is: exactly what settle() would get from the cloth-motion model (whose checks the
    // input has passed), written directly because a crowd of resting balls would otherwise pay for
    // those calls one by one.
    if (b.state.velocity.isZero(0) && b.state.angular_velocity.isZero(0)) {
      starts_at_rest[i] = 1;
      b.path.constant_m = b.state.position;
      b.box = Box::around(b.state.position, R);
      continue;
    }
    settle(i, 0);
  }
  // The path of ball i from time t on (a shift of its quadratic).
  auto pathFrom = [&](int i, double t) {
    const Ball& b = balls[i];
    const double s = t - b.reference_time_s;
    if (s == 0) return b.path;
    physics::PositionQuadratic shifted = b.path;
    shifted.constant_m = b.path.at(s);
    shifted.linear_mps = b.path.linear_mps + 2 * s * b.path.quadratic_mps2;
    return shifted;
  };
  std::vector<Box> cushion_boxes, jaw_boxes, pocket_boxes;
  cushion_boxes.reserve(table.cushions.size());
  jaw_boxes.reserve(table.jaws.size());
  pocket_boxes.reserve(table.pockets.size());
  for (const CushionSegment& c : table.cushions)
    cushion_boxes.push_back(Box::spanning(c.start_m, c.end_m));
  for (const JawArc& jaw : table.jaws) jaw_boxes.push_back(Box::around(jaw.centre_m, jaw.radius_m));
  for (const Circle& pocket : table.pockets)
    pocket_boxes.push_back(Box::around(pocket.centre_m, pocket.radius_m));

  double now = 0;
  Candidate last;  // the contact resolved last, not to be found again at the same instant
  bool last_valid = false;

  // Predictions, as absolute times, stay valid until one of their balls changes its motion; only
  // those are solved again. own: a ball's state change, cushion, jaw or pocket; pair_time: when
  // balls i < j touch, at [i * n + j]; next: each ball's earliest of its own and its pairs'.
  std::vector<Candidate> own(n), next(n);
  // Left unset (filling n^2 entries would cost more than a whole shot among many resting balls):
  // a pair's time is read only through `partners`, which lists only pairs whose time was written.
  std::unique_ptr<double[]> pair_time(new double[static_cast<std::size_t>(n) * n]);
  // Per ball, every ball it has a finite pair time with (and some it no longer has, and repeats;
  // right after a ball changed and was predicted again, exactly those it has):
  // what a ball's earliest candidate and a change of its motion need to look at, not every ball.
  std::vector<std::vector<int>> partners(n);
  auto pairCandidate = [&](int i, int j) {
    if (i > j) std::swap(i, j);
    return Candidate{pair_time[static_cast<std::size_t>(i) * n + j], EventKind::BallBall, i, j};
  };
  // The first closing root of a gap polynomial in [0, horizon]; a gap the cheap bound shows to
  // stay open is counted as skipped instead of solved.
  auto solve = [&](const PolynomialCoefficients& gap, double horizon) {
    if (staysApart(gap, horizon)) {
      ++result.skipped_predictions;
      return physics::RootSearchResult{};
    }
    ++result.predictions;
    return physics::firstClosingRoot(gap, 0, horizon);
  };
  // A prediction made now: dt from now, stored as an absolute time (the just-resolved contact is
  // not found again at the same instant).
  auto absolute = [&](Candidate c) {
    if (last_valid && c.dt_s == 0 && c.sameContact(last)) c.dt_s = kInfinity;
    c.dt_s += now;
    return c;
  };
  // Impacts solved ahead (engine/sim/cushion_solve_ahead.h): ball i's earliest event, if it is a
  // cushion or jaw contact, from the state the ball will have then, as moveTo() will find it. The
  // simple rule costs less than handing it over.
  CushionSolveAhead ahead(p, n);
  const bool solve_ahead = p.cushion_model != CushionModelChoice::SimpleRestitution;
  auto solveAhead = [&](int i) {
    const Candidate& c = next[i];
    if (!(c.dt_s < kInfinity) || (c.kind != EventKind::Cushion && c.kind != EventKind::Jaw)) {
      ahead.forget(i);
      return;
    }
    const Ball& b = balls[i];
    BallState at = b.state;
    const double dt = std::min(c.dt_s - b.reference_time_s, b.change_dt_s);
    if (dt > 0) at = physics::advanceWithinState(p.cloth, at, dt);
    const physics::BallVelocity local =
        ContactFrame(contactNormal(table, c.kind, c.index, at.position)).toLocal(at);
    if (local.v.y() > 0)
      ahead.predict(i, c.dt_s, local);
    else
      ahead.forget(i);
  };
  auto predictOwn = [&](int i) {  // ball i was settled at `now`
    Ball& b = balls[i];
    Candidate best_own{b.change_dt_s, EventKind::StateChange, i};
    // The ball's motion changes at its first own event: nothing after it needs predicting, so the
    // horizon and the swept box shrink to it as events are found (cushions first: cheap).
    double horizon = b.change_dt_s;
    if (b.moves) {
      const physics::PositionQuadratic& path = b.path;
      auto shrinkTo = [&](const Candidate& found) {
        horizon = found.dt_s;
        b.box = sweptBox(path, horizon, R);
      };
      for (int k = 0; k < static_cast<int>(table.cushions.size()); ++k) {
        if (!b.box.overlaps(cushion_boxes[k])) {
          ++result.skipped_predictions;
          continue;
        }
        const CushionSegment& c = table.cushions[k];
        const PolynomialCoefficients gap = {c.inward_normal.dot(path.constant_m - c.start_m) - R,
                                            c.inward_normal.dot(path.linear_mps),
                                            c.inward_normal.dot(path.quadratic_mps2), 0, 0};
        const physics::RootSearchResult hit = solve(gap, horizon);
        if (hit.outcome != physics::RootOutcome::Root) continue;
        const Eigen::Vector2d along = c.end_m - c.start_m;
        const double s = (path.at(hit.time) - c.start_m).dot(along) / along.squaredNorm();
        const Candidate candidate{hit.time, EventKind::Cushion, i, -1, k};
        if (s >= 0 && s <= 1 && absolute(candidate).dt_s < kInfinity && candidate < best_own)
          best_own = candidate;
      }
      shrinkTo(best_own);
      for (int k = 0; k < static_cast<int>(table.jaws.size()); ++k) {
        if (!b.box.overlaps(jaw_boxes[k])) {
          ++result.skipped_predictions;
          continue;
        }
        const JawArc& jaw = table.jaws[k];
        if (staysFarther(path.constant_m - jaw.centre_m, path.linear_mps, path.quadratic_mps2,
                         jaw.radius_m + R, horizon)) {
          ++result.skipped_predictions;
          continue;
        }
        const PolynomialCoefficients gap = squaredGap(path, jaw.centre_m, Eigen::Vector2d::Zero(),
                                                      Eigen::Vector2d::Zero(), jaw.radius_m + R);
        const physics::RootSearchResult hit = solve(gap, horizon);
        const Candidate candidate{hit.time, EventKind::Jaw, i, -1, k};
        if (hit.outcome == physics::RootOutcome::Root && onJawArc(jaw, path.at(hit.time)) &&
            absolute(candidate).dt_s < kInfinity && candidate < best_own) {
          best_own = candidate;
        }
      }
      shrinkTo(best_own);
      for (int k = 0; k < static_cast<int>(table.pockets.size()); ++k) {
        if (!b.box.overlaps(pocket_boxes[k])) {
          ++result.skipped_predictions;
          continue;
        }
        const Circle& pocket = table.pockets[k];
        if (staysFarther(path.constant_m - pocket.centre_m, path.linear_mps, path.quadratic_mps2,
                         pocket.radius_m, horizon)) {
          ++result.skipped_predictions;
          continue;
        }
        const PolynomialCoefficients gap =
            squaredGap(path, pocket.centre_m, Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(),
                       pocket.radius_m);
        const physics::RootSearchResult hit = solve(gap, horizon);
        const Candidate candidate{hit.time, EventKind::Pocket, i, -1, k};
        if (hit.outcome == physics::RootOutcome::Root && candidate < best_own) best_own = candidate;
      }
      shrinkTo(best_own);
    }
    b.valid_until_s = now + horizon;
    own[i] = absolute(best_own);
  };
  auto predictPair = [&](int i, int j) {  // i settled at `now`
    double& cached = pair_time[static_cast<std::size_t>(std::min(i, j)) * n + std::max(i, j)];
    cached = kInfinity;
    const Ball &bi = balls[i], &bj = balls[j];
    if (bj.pocketed) return;
    if (!bi.moves && !bj.moves) {
      ++result.skipped_predictions;
      return;
    }
    // Cheap bound first: the boxes the two sweep until either changes state do not meet.
    if (!bi.box.overlaps(bj.box)) {
      ++result.skipped_predictions;
      return;
    }
    const double horizon = std::min(bi.moves ? bi.valid_until_s - now : kInfinity,
                                    bj.moves ? bj.valid_until_s - now : kInfinity);
    const physics::PositionQuadratic path_i = bi.path, path_j = pathFrom(j, now);
    const int a = std::min(i, j), b = std::max(i, j);  // the gap of the lower-numbered ball
    const physics::PositionQuadratic& pa = a == i ? path_i : path_j;
    const physics::PositionQuadratic& pb = a == i ? path_j : path_i;
    if (staysFarther(pa.constant_m - pb.constant_m, pa.linear_mps - pb.linear_mps,
                     pa.quadratic_mps2 - pb.quadratic_mps2, 2 * R, std::max(0.0, horizon))) {
      ++result.skipped_predictions;
      return;
    }
    const PolynomialCoefficients gap =
        squaredGap(pa, pb.constant_m, pb.linear_mps, pb.quadratic_mps2, 2 * R);
    const physics::RootSearchResult hit = solve(gap, std::max(0.0, horizon));
    if (hit.outcome == physics::RootOutcome::Root)
      cached = absolute({hit.time, EventKind::BallBall, a, b}).dt_s;
    if (cached < kInfinity) {
      partners[a].push_back(b);
      partners[b].push_back(a);
    }
  };
  // Ball k's earliest candidate, from scratch. Its list of partners is cleaned on the way (pairs
  // since predicted empty and repeats dropped), so that it cannot grow with every event of a
  // neighbour while ball k itself has none.
  std::vector<char> listed(n, 0);  // in the cleaned list, by ball
  auto rescan = [&](int k) {
    Candidate best = own[k];
    std::vector<int>& list = partners[k];
    std::size_t kept = 0;
    for (std::size_t m = 0; m < list.size(); ++m) {
      const int j = list[m];
      const Candidate c = pairCandidate(k, j);
      if (!(c.dt_s < kInfinity) || listed[j]) continue;
      listed[j] = 1;
      list[kept++] = j;
      if (c < best) best = c;
    }
    list.resize(kept);
    for (int j : list) listed[j] = 0;
    next[k] = best;
  };
  // A pair's prediction is finite only while one of its balls moves (it is predicted again when
  // either changes), so the next event is the earliest candidate of a ball that moves or has an
  // event of its own ahead (a spinning ball's stop): only those "active" balls' earliest candidates
  // are kept, and a resting ball costs nothing per event.
  std::vector<int> active, movers;                     // movers: the active balls that move
  std::vector<char> is_active(n, 0), rescanned(n, 0);  // rescanned: its candidate found anew
  // The balls resting at the start, by place; those that come to rest later are looked at one by
  // one (a few at most, in practice).
  std::vector<int> initially_resting, resting_later;
  for (int i = 0; i < n; ++i)
    if (!balls[i].moves) initially_resting.push_back(i);
  const RestingGrid resting_grid(initially_resting, input, R);
  std::vector<char> in_grid(n, 0), is_resting_later(n, 0);
  for (int i : initially_resting) in_grid[i] = 1;
  int on_table = n;                  // balls not pocketed
  std::vector<int> self_predicting;  // changed balls that predict their pairs with changed balls

  std::vector<int> changed;            // balls whose motion changed at the last event
  std::vector<char> is_changed(n, 0);  // the same, by ball
  // In the first pass every ball is new, but a ball exactly at rest has nothing to predict (no
  // event of its own, and its pairs with the moving balls are predicted by those): it is only
  // counted among the resting ones, so a crowd of them costs nothing there either.
  long resting_from_start = 0;
  for (int i = 0; i < n; ++i) {
    if (starts_at_rest[i]) {
      own[i] = Candidate{kInfinity, EventKind::StateChange, i};  // what predictOwn() would give
      ++resting_from_start;
      continue;
    }
    changed.push_back(i);
    is_changed[i] = 1;
  }
  bool first_pass = true;  // every ball is new; pairs of resting balls are left unpredicted
  for (long count = 0;; ++count) {
    if (count == p.max_events) {
      throw std::runtime_error(
          "the shot did not come to rest within max_events = " + std::to_string(p.max_events) +
          " events (at t = " + physics::valueText(now) + " s)");
    }
    // Predict again what involves a ball that changed; each other ball's earliest candidate is
    // then updated with its new pairs, or found again if it was one of the stale ones.
    long resting = 0;  // first pass: balls at rest, whose pairs are skipped
    // Every pair of a changed ball is predicted again (or left empty): clear the old ones.
    for (int i : changed) {
      for (int j : partners[i])
        pair_time[static_cast<std::size_t>(std::min(i, j)) * n + std::max(i, j)] = kInfinity;
      partners[i].clear();
    }
    // Own events first: a pair is predicted only as far as both balls' paths hold.
    for (int i : changed) {
      if (!balls[i].pocketed) {
        predictOwn(i);
        continue;
      }
      own[i] = Candidate{};
      ahead.forget(i);
    }
    for (int i : changed) {
      const bool now_active = !balls[i].pocketed && (balls[i].moves || own[i].dt_s < kInfinity);
      if (now_active != static_cast<bool>(is_active[i])) {
        is_active[i] = now_active;
        if (now_active)
          active.push_back(i);
        else
          active.erase(std::find(active.begin(), active.end(), i));
      }
      if (first_pass) continue;
      // Its place in the grid no longer holds; at rest, it is looked at one by one.
      in_grid[i] = 0;
      if (!balls[i].moves && !balls[i].pocketed && !is_resting_later[i]) {
        is_resting_later[i] = 1;
        resting_later.push_back(i);
      }
    }
    movers.clear();
    for (int k : active)
      if (balls[k].moves) movers.push_back(k);
    // A pair of two changed balls is predicted once, by the lower-numbered one (or, in the first
    // pass, by the moving one).
    self_predicting.clear();
    for (int i : changed)
      if (!balls[i].pocketed && !(first_pass && !balls[i].moves)) self_predicting.push_back(i);
    std::sort(self_predicting.begin(), self_predicting.end());
    for (int i : changed) {
      if (balls[i].pocketed) continue;
      if (first_pass && !balls[i].moves) {  // its pairs with resting balls: already empty
        ++resting;
        continue;
      }
      // Ball i's pairs: with every ball that moves, and, if it moves, with the resting balls its
      // swept box reaches. Every other ball on the table is a pair predictPair() would skip (both
      // at rest, or boxes apart), counted as such.
      long visited = 0;
      auto visit = [&](int j) {
        predictPair(i, j);
        ++visited;
      };
      for (int j : movers)
        if (j != i && !(j < i && is_changed[j])) visit(j);
      if (balls[i].moves) {
        auto visitResting = [&](int j) {
          if (balls[j].moves || balls[j].pocketed || !balls[j].box.overlaps(balls[i].box)) return;
          if (j < i && is_changed[j] && !first_pass) return;
          visit(j);
        };
        resting_grid.forEachNear(balls[i].box, R + kBoxMargin_m, [&](int j) {
          if (in_grid[j]) visitResting(j);
        });
        for (int j : resting_later) visitResting(j);
      }
      const long predicted_elsewhere =
          std::lower_bound(self_predicting.begin(), self_predicting.end(), i) -
          self_predicting.begin();
      result.skipped_predictions += (on_table - 1) - predicted_elsewhere - visited;
    }
    if (first_pass) {
      resting += resting_from_start;
      result.skipped_predictions += resting * (resting - 1) / 2;
    }
    first_pass = false;
    for (int k : active) {
      rescanned[k] =
          is_changed[k] ||
          (next[k].dt_s < kInfinity &&
           (is_changed[next[k].ball] || (next[k].other >= 0 && is_changed[next[k].other])));
      if (rescanned[k]) rescan(k);
    }
    // The others gain the changed balls' new pairs (their finite ones: all in `partners` now).
    for (int i : changed) {
      for (int k : partners[i]) {
        if (!is_active[k] || rescanned[k]) continue;
        const Candidate c = pairCandidate(k, i);
        if (c.dt_s < kInfinity && c < next[k]) {
          next[k] = c;
          ahead.forget(k);  // its contact, if one was handed over, now comes after this pair's
        }
      }
    }
    // A ball whose earliest event is now a cushion or jaw contact has it solved ahead, while other
    // balls move too (a lone ball's next events are its own: nothing to overlap with).
    if (solve_ahead && ahead.mayUse()) {
      for (int k : active) {
        if (!rescanned[k]) continue;
        if (movers.size() >= 2)
          solveAhead(k);
        else
          ahead.forget(k);
      }
    }
    Candidate best;
    for (int k : active)
      if (next[k].dt_s < kInfinity && next[k] < best) best = next[k];
    if (!(best.dt_s < kInfinity)) break;                 // every ball at rest or pocketed
    const double event_time = std::max(best.dt_s, now);  // rounding of absolute times
    for (int i : changed) is_changed[i] = 0;
    changed.clear();

    // Move the balls involved to the event's instant. A state change happens exactly at the ball's
    // transition time, where advanceWithinState sets the next state exactly.
    auto moveTo = [&](int i) {
      Ball& b = balls[i];
      const double dt = best.kind == EventKind::StateChange
                            ? b.change_dt_s
                            : std::min(event_time - b.reference_time_s, b.change_dt_s);
      if (dt > 0) b.state = physics::advanceWithinState(p.cloth, b.state, dt);
    };
    if (best.kind == EventKind::StateChange && !(balls[best.ball].change_dt_s < kInfinity)) {
      changed.push_back(best.ball);  // a stale prediction: predict it again
      is_changed[best.ball] = 1;
      continue;
    }
    moveTo(best.ball);
    if (best.kind == EventKind::BallBall) moveTo(best.other);
    now = event_time;
    last = best;
    last_valid = true;

    Event event;
    event.time_s = now;
    event.kind = best.kind;
    event.ball = best.ball;
    event.other = best.other;
    event.index = best.index;
    BallState& a = balls[best.ball].state;
    const physics::PositionQuadratic path_a = balls[best.ball].path;
    event.before.push_back(a);
    if (best.kind == EventKind::BallBall) event.before.push_back(balls[best.other].state);
    switch (best.kind) {
      case EventKind::StateChange:
        break;  // advanceWithinState set the next state exactly
      case EventKind::Pocket:
        balls[best.ball].pocketed = true;
        balls[best.ball].pocket = best.index;
        --on_table;
        break;
      case EventKind::Cushion:
      case EventKind::Jaw: {
        // The chosen cushion model (engine/sim/cushion_contact.h) in the frame of the contact normal,
        // or the helper's answer from the same input.
        const Eigen::Vector2d normal = contactNormal(table, best.kind, best.index, a.position);
        const ContactFrame frame(normal);
        const physics::BallVelocity local = frame.toLocal(a);
        const bool pressed = path_a.quadratic_mps2.dot(normal) < 0;
        if (local.v.y() > 0 || pressed) {
          physics::BallVelocity after = local;
          if (local.v.y() > 0) after = ahead.resolve(best.ball, local);
          // In the cushion's frame the normal into the table is -y.
          if (pressed)
            releasePressedContact(p.cushion, physics::kineticEnergy(p.cushion, local),
                                  Eigen::Vector3d(0, -1, 0), &after, nullptr);
          frame.toTable(after, &a);
        }
        break;
      }
      case EventKind::BallBall: {
        BallState& b = balls[best.other].state;
        Eigen::Vector3d normal(b.position.x() - a.position.x(), b.position.y() - a.position.y(), 0);
        normal.normalize();
        const physics::BallVelocity va{a.velocity, a.angular_velocity},
            vb{b.velocity, b.angular_velocity};
        const bool approaching = physics::approachSpeed(va, vb, normal) > 0;
        const bool pressed =
            (path_a.quadratic_mps2 - balls[best.other].path.quadratic_mps2).dot(normal.head<2>()) >
            0;
        if (approaching || pressed) {
          physics::BallVelocity a_after = va, b_after = vb;
          if (approaching) {
            const physics::BallBallImpactResult impact =
                physics::resolveBallBallImpact(p.ball_ball, va, vb, normal);
            a_after = impact.ball1;
            b_after = impact.ball2;
          }
          if (pressed) {
            releasePressedContact(
                p.cushion,
                physics::kineticEnergy(p.cushion, va) + physics::kineticEnergy(p.cushion, vb),
                normal, &a_after, &b_after);
          }
          a.velocity = a_after.v;
          a.angular_velocity = a_after.w;
          b.velocity = b_after.v;
          b.angular_velocity = b_after.w;
        }
        break;
      }
    }
    event.after.push_back(a);
    if (best.kind == EventKind::BallBall) event.after.push_back(balls[best.other].state);
    changed.push_back(best.ball);
    is_changed[best.ball] = 1;
    settle(best.ball, now);
    if (best.kind == EventKind::BallBall) {
      changed.push_back(best.other);
      is_changed[best.other] = 1;
      settle(best.other, now);
    }
    // Every ball that moves ends its motion at an event of its own, so checking the balls of each
    // event finds any that left (one point-in-polygon test per ball per event).
    if (!table.outline.empty()) {
      requireOnTable(table, event, best.ball, balls[best.ball].pocketed, a, ball_ids);
      if (best.kind == EventKind::BallBall) {
        requireOnTable(table, event, best.other, false, balls[best.other].state, ball_ids);
      }
    }
    if (p.record_trajectories &&
        best.kind != EventKind::StateChange) {  // a state change is in closed form
      result.trajectories[best.ball].push_back({now, a, balls[best.ball].pocketed});
      if (best.kind == EventKind::BallBall)
        result.trajectories[best.other].push_back({now, balls[best.other].state, false});
    }
    result.events.push_back(std::move(event));
  }
  // Balls at rest are reported exactly at rest (a speed below the at-rest threshold, left by a
  // transition a rounding early, is not motion).
  result.final_balls.resize(n);
  for (int i = 0; i < n; ++i) {
    result.final_balls[i].pocketed = balls[i].pocketed;
    result.final_balls[i].pocket = balls[i].pocket;
    const BallState& b = balls[i].state;
    const bool exactly_at_rest = b.velocity.isZero(0) && b.angular_velocity.isZero(0);
    result.final_balls[i].state =
        balls[i].pocketed || exactly_at_rest ? b : physics::advanceWithinState(p.cloth, b, 0);
  }
  result.end_time_s = now;
  return result;
}

}  // namespace baize::engine
