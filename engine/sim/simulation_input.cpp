#include "engine/sim/simulation_input.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "engine/sim/contact_geometry.h"
#include "physics/value_text.h"

namespace baize::engine {
namespace {

using physics::BallState;
using Namer = std::function<std::string(std::size_t)>;

// Balls may start this much closer than touching (m) and still count as touching: positions written
// in a scene file or placed by a rack round to about this.
constexpr double kContactSlack_m = 1e-9;

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

// The parameters: a model chosen for each kind of contact, each model's own checks with the shot's
// ball and cloth, and the cloth's copy of the ball radius the ball's.
void validateParams(const SimulationParams& p) {
  if (!p.cushion || !p.ball_ball) {
    throw std::invalid_argument(
        "a missing cushion or ball-ball model is not allowed: choose one by name "
        "(engine/models/model_registry.h)");
  }
  physics::validateClothParams(p.cloth);
  p.cushion->validate(p);
  p.ball_ball->validate(p);
  if (p.cloth.radius_m != p.ball.radius_m) {
    physics::rejectValue("ball radius of the cloth parameters (m)", p.cloth.radius_m,
                         "it must equal the ball's radius " + physics::valueText(p.ball.radius_m));
  }
  if (!(p.max_events > 0))
    physics::rejectValue("max_events", static_cast<double>(p.max_events), "it must be > 0");
}

// The table: unit normals, cushions of some length, jaws of a radius and at most a turn.
void validateTableShape(const TableGeometry& table) {
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
}

// Each ball's state: finite, and speeds and spins within what every impact model takes.
void validateBallStates(const std::vector<BallState>& balls, const Namer& who) {
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
}

void checkNoOverlaps(const std::vector<BallState>& balls, double R, const Namer& who) {
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
        physics::rejectValue(who(i) + " overlaps " + who(j) + ": their gap (m)", gap,
                             "balls may touch but not overlap (gap >= 0)");
      }
    }
  }
}

// Every ball within the table's extent, and none beyond a cushion or inside a jaw.
void checkOnTable(const TableGeometry& table, const std::vector<BallState>& balls, double R,
                  const Namer& who) {
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

}  // namespace

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
      ballName(ids, static_cast<std::size_t>(ball)) +
      " left the table: at t = " + physics::valueText(event.time_s) + " s (a " +
      eventKindName(event.kind) + " event) its centre [" + physics::valueText(state.position.x()) +
      ", " + physics::valueText(state.position.y()) +
      "] m is outside the table's cushion outline and not in a pocket (a capture circle that "
      "does not cover its pocket's opening lets balls through)");
}

void validateSimulationInput(const SimulationParams& p, const TableGeometry& table,
                             const std::vector<BallState>& balls,
                             const std::vector<std::string>& ball_ids) {
  if (!ball_ids.empty() && ball_ids.size() != balls.size()) {
    physics::rejectValue("number of ball ids", static_cast<double>(ball_ids.size()),
                         "it must be 0 or the number of balls, " + std::to_string(balls.size()));
  }
  validateParams(p);
  validateTableShape(table);
  const Namer who = [&](std::size_t i) { return ballName(ball_ids, i); };
  validateBallStates(balls, who);
  checkNoOverlaps(balls, p.ball.radius_m, who);
  checkOnTable(table, balls, p.ball.radius_m, who);
}

}  // namespace baize::engine
