#include "engine/shot_simulator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <tuple>

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

// Whether gap polynomial p stays positive on [0, horizon] by the bound p(t) >= c0 - sum |c_k| T^k:
// then it has no root there and the root finder need not run.
bool staysApart(const PolynomialCoefficients& p, double horizon) {
  if (!(p[0] > 0) || !std::isfinite(horizon)) return false;
  double bound = 0, power = 1;
  for (int k = 1; k < 5; ++k) {
    power *= horizon;
    bound += std::abs(p[k]) * power;
  }
  return p[0] - bound > 0;
}

// Furthest a ball can travel within dt along its current path, m (a bound, for skipping pairs).
double reach(const physics::PositionQuadratic& path, double dt) {
  return path.linear_mps.norm() * dt + path.quadratic_mps2.norm() * dt * dt;
}

// The cushion's local frame: y into the cushion (against the inward normal), x along it, z up.
struct CushionFrame {
  Eigen::Vector3d x, y;
  explicit CushionFrame(const Eigen::Vector2d& inward_normal)
      : x(-inward_normal.y(), inward_normal.x(), 0), y(-inward_normal.x(), -inward_normal.y(), 0) {}
  physics::BallVelocity toLocal(const BallState& ball) const {
    physics::BallVelocity local;
    local.v = {ball.velocity.dot(x), ball.velocity.dot(y), 0};
    local.w = {ball.angular_velocity.dot(x), ball.angular_velocity.dot(y),
               ball.angular_velocity.z()};
    return local;
  }
  void toTable(const physics::BallVelocity& local, BallState* ball) const {
    ball->velocity = local.v.x() * x + local.v.y() * y;
    ball->velocity.z() = 0;
    ball->angular_velocity = local.w.x() * x + local.w.y() * y + Eigen::Vector3d(0, 0, local.w.z());
  }
};

// Whether the direction from a jaw's centre to point q lies within the jaw's angular range.
bool onArc(const JawArc& jaw, const Eigen::Vector2d& q) {
  double angle = std::atan2(q.y() - jaw.centre_m.y(), q.x() - jaw.centre_m.x());
  while (angle < jaw.start_angle_rad) angle += 2 * M_PI;
  return angle <= jaw.end_angle_rad;
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

void validateInput(const SimulationParams& p, const TableGeometry& table,
                   const std::vector<BallState>& balls) {
  physics::validateClothParams(p.cloth);
  physics::validateCushionParams(p.cushion);
  physics::validateBallBallParams(p.ball_ball);
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
  for (std::size_t i = 0; i < balls.size(); ++i) {
    const std::string who = "ball " + std::to_string(i);
    try {
      physics::validateBallState(balls[i]);
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(who + ": " + e.what());
    }
    for (std::size_t j = 0; j < i; ++j) {
      const double gap = (balls[i].position - balls[j].position).norm() - 2 * R;
      if (gap < -kContactSlack_m) {
        physics::rejectValue(who + " overlaps ball " + std::to_string(j) + ": their gap (m)", gap,
                             "balls may touch but not overlap (gap >= 0)");
      }
    }
    for (std::size_t k = 0; k < table.jaws.size(); ++k) {
      const JawArc& jaw = table.jaws[k];
      const double distance = (balls[i].position - jaw.centre_m).norm();
      if (onArc(jaw, balls[i].position) && distance < jaw.radius_m + R - kContactSlack_m) {
        physics::rejectValue(who + " is inside jaw " + std::to_string(k) +
                                 ": its centre's distance from the jaw's centre (m)",
                             distance, "it must be at least the jaw's radius plus the ball's");
      }
    }
    for (std::size_t k = 0; k < table.cushions.size(); ++k) {
      const CushionSegment& c = table.cushions[k];
      const Eigen::Vector2d along = c.end_m - c.start_m;
      const double s = (balls[i].position - c.start_m).dot(along) / along.squaredNorm();
      const double distance = c.inward_normal.dot(balls[i].position - c.start_m);
      if (s >= 0 && s <= 1 && distance < R - kContactSlack_m) {
        physics::rejectValue(
            who + " is beyond cushion " + std::to_string(k) + ": its centre's distance from it (m)",
            distance, "it must be at least the radius " + physics::valueText(R));
      }
    }
  }
}

}  // namespace

TableGeometry rectangularTable(double length_m, double width_m) {
  if (!(length_m > 0 && std::isfinite(length_m)))
    physics::rejectValue("table length (m)", length_m, "it must be > 0");
  if (!(width_m > 0 && std::isfinite(width_m)))
    physics::rejectValue("table width (m)", width_m, "it must be > 0");
  const double x = length_m / 2, y = width_m / 2;
  TableGeometry table;
  table.cushions = {{{-x, -y}, {x, -y}, {0, 1}},
                    {{x, -y}, {x, y}, {-1, 0}},
                    {{x, y}, {-x, y}, {0, -1}},
                    {{-x, y}, {-x, -y}, {1, 0}}};
  return table;
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

TableGeometry geometryOf(const Table& table) {
  TableGeometry geometry;
  geometry.cushions = table.cushions;
  geometry.jaws = table.jaw_arcs;
  for (const Pocket& pocket : table.pockets) geometry.pockets.push_back(pocket.capture);
  return geometry;
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
                          const std::vector<BallState>& input) {
  validateInput(p, table, input);
  const double R = p.cushion.radius_m;
  SimulationResult result;
  std::vector<BallRecord> balls(input.size());
  for (std::size_t i = 0; i < input.size(); ++i) balls[i].state = input[i];
  if (p.record_trajectories) {
    result.trajectories.resize(input.size());
    for (std::size_t i = 0; i < input.size(); ++i)
      result.trajectories[i].push_back({0, input[i], false});
  }
  double now = 0;
  Candidate last;  // the contact resolved last, not to be found again at the same instant
  bool last_valid = false;

  // Predictions are cached as absolute times and stay valid until one of their balls changes its
  // motion (an event involving it, or its own state change): only those are solved again.
  const int n = static_cast<int>(balls.size());
  std::vector<Candidate> own(n);  // per ball: state change, cushion, jaw, pocket
  std::vector<Candidate> pair(static_cast<std::size_t>(n) * n);  // per pair i < j at [i * n + j]
  std::vector<bool> dirty(n, true);
  std::vector<double> until(n, kInfinity);  // time from now to each ball's next state change
  std::vector<physics::PositionQuadratic> path(n);
  std::vector<char> moves(n, 0);  // sliding or rolling now

  for (long count = 0;; ++count) {
    if (count == p.max_events) {
      throw std::runtime_error(
          "the shot did not come to rest within max_events = " + std::to_string(p.max_events) +
          " events (at t = " + physics::valueText(now) + " s)");
    }
    for (int i = 0; i < n; ++i) {
      if (balls[i].pocketed) continue;
      until[i] = physics::timeToStateChange(p.cloth, balls[i].state);
      path[i] = physics::positionQuadratic(p.cloth, balls[i].state);
      moves[i] = moving(p.cloth, balls[i].state);
    }
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
    for (int i = 0; i < n; ++i) {
      if (!dirty[i]) continue;
      own[i] = Candidate{};
      if (balls[i].pocketed) continue;
      Candidate best_own{until[i], EventKind::StateChange, i};
      if (moves[i]) {
        const double horizon = until[i];
        for (int k = 0; k < static_cast<int>(table.cushions.size()); ++k) {
          const CushionSegment& c = table.cushions[k];
          const PolynomialCoefficients gap = {
              c.inward_normal.dot(path[i].constant_m - c.start_m) - R,
              c.inward_normal.dot(path[i].linear_mps), c.inward_normal.dot(path[i].quadratic_mps2),
              0, 0};
          const physics::RootSearchResult hit = solve(gap, horizon);
          if (hit.outcome != physics::RootOutcome::Root) continue;
          const Eigen::Vector2d along = c.end_m - c.start_m;
          const double s = (path[i].at(hit.time) - c.start_m).dot(along) / along.squaredNorm();
          const Candidate candidate{hit.time, EventKind::Cushion, i, -1, k};
          if (s >= 0 && s <= 1 && absolute(candidate).dt_s < kInfinity && candidate < best_own)
            best_own = candidate;
        }
        for (int k = 0; k < static_cast<int>(table.jaws.size()); ++k) {
          const JawArc& jaw = table.jaws[k];
          const PolynomialCoefficients gap =
              squaredGap(path[i], jaw.centre_m, Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(),
                         jaw.radius_m + R);
          const physics::RootSearchResult hit = solve(gap, horizon);
          const Candidate candidate{hit.time, EventKind::Jaw, i, -1, k};
          if (hit.outcome == physics::RootOutcome::Root && onArc(jaw, path[i].at(hit.time)) &&
              absolute(candidate).dt_s < kInfinity && candidate < best_own) {
            best_own = candidate;
          }
        }
        for (int k = 0; k < static_cast<int>(table.pockets.size()); ++k) {
          const Circle& pocket = table.pockets[k];
          const PolynomialCoefficients gap =
              squaredGap(path[i], pocket.centre_m, Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero(),
                         pocket.radius_m);
          const physics::RootSearchResult hit = solve(gap, horizon);
          const Candidate candidate{hit.time, EventKind::Pocket, i, -1, k};
          if (hit.outcome == physics::RootOutcome::Root && candidate < best_own)
            best_own = candidate;
        }
      }
      own[i] = absolute(best_own);
    }
    for (int i = 0; i < n; ++i) {
      for (int j = i + 1; j < n; ++j) {
        if (!dirty[i] && !dirty[j]) continue;
        Candidate& cached = pair[static_cast<std::size_t>(i) * n + j];
        cached = Candidate{};
        if (balls[i].pocketed || balls[j].pocketed) continue;
        const bool i_moves = moves[i], j_moves = moves[j];
        if (!i_moves && !j_moves) {
          ++result.skipped_predictions;
          continue;
        }
        const double horizon =
            std::min(i_moves ? until[i] : kInfinity, j_moves ? until[j] : kInfinity);
        // Cheap bound first: too far apart to meet before either changes state.
        const double apart = (balls[i].state.position - balls[j].state.position).norm() - 2 * R;
        if (apart > reach(path[i], horizon) + reach(path[j], horizon)) {
          ++result.skipped_predictions;
          continue;
        }
        const PolynomialCoefficients gap = squaredGap(
            path[i], path[j].constant_m, path[j].linear_mps, path[j].quadratic_mps2, 2 * R);
        const physics::RootSearchResult hit = solve(gap, horizon);
        if (hit.outcome == physics::RootOutcome::Root)
          cached = absolute({hit.time, EventKind::BallBall, i, j});
      }
    }
    std::fill(dirty.begin(), dirty.end(), false);
    Candidate best;
    for (const Candidate& c : own)
      if (c.dt_s < kInfinity && c < best) best = c;
    for (const Candidate& c : pair)
      if (c.dt_s < kInfinity && c < best) best = c;
    if (!(best.dt_s < kInfinity)) break;  // every ball at rest or pocketed
    best.dt_s -= now;                     // back to time from now
    if (best.dt_s < 0) best.dt_s = 0;     // rounding of the absolute time
    // A state change happens exactly at the ball's transition time, where advanceWithinState sets
    // the next state exactly (the absolute time round trip may have moved it by a rounding).
    if (best.kind == EventKind::StateChange) {
      if (!(until[best.ball] < kInfinity)) {  // a stale prediction: the ball is already at rest
        dirty[best.ball] = true;
        continue;
      }
      best.dt_s = until[best.ball];
    }

    // Move every ball to the event's instant.
    for (int i = 0; i < n; ++i) {
      if (balls[i].pocketed) continue;
      const double dt = std::min(best.dt_s, until[i]);
      const physics::MotionState was = physics::motionState(p.cloth, balls[i].state);
      if (dt > 0) balls[i].state = physics::advanceWithinState(p.cloth, balls[i].state, dt);
      // Its motion changed on the way (at its transition time, or a rounding before it): predict it
      // again.
      if (dt == until[i] || physics::motionState(p.cloth, balls[i].state) != was) dirty[i] = true;
    }
    now += best.dt_s;
    last = best;
    last_valid = true;

    Event event;
    event.time_s = now;
    event.kind = best.kind;
    event.ball = best.ball;
    event.other = best.other;
    event.index = best.index;
    BallState& a = balls[best.ball].state;
    event.before.push_back(a);
    if (best.kind == EventKind::BallBall) event.before.push_back(balls[best.other].state);
    switch (best.kind) {
      case EventKind::StateChange:
        break;  // advanceWithinState set the next state exactly
      case EventKind::Pocket:
        balls[best.ball].pocketed = true;
        break;
      case EventKind::Cushion:
      case EventKind::Jaw: {
        // The seed model in the frame of the contact normal: a straight cushion's, or the direction
        // from a jaw's centre to the ball.
        const Eigen::Vector2d normal =
            best.kind == EventKind::Cushion
                ? table.cushions[best.index].inward_normal
                : Eigen::Vector2d((a.position - table.jaws[best.index].centre_m).normalized());
        const CushionFrame frame(normal);
        const physics::BallVelocity local = frame.toLocal(a);
        const bool pressed = path[best.ball].quadratic_mps2.dot(normal) < 0;
        if (local.v.y() > 0 || pressed) {
          physics::BallVelocity after = local;
          if (local.v.y() > 0)
            after = physics::solveCushionImpactExact(p.cushion, local, p.cushion_solver).after;
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
        const bool pressed = (path[best.ball].quadratic_mps2 - path[best.other].quadratic_mps2)
                                 .dot(normal.head<2>()) > 0;
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
    dirty[best.ball] = true;
    if (best.kind == EventKind::BallBall) dirty[best.other] = true;
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
  for (BallRecord& b : balls) {
    if (!b.pocketed) b.state = physics::advanceWithinState(p.cloth, b.state, 0);
  }
  result.final_balls = balls;
  result.end_time_s = now;
  return result;
}

}  // namespace baize::engine
