#include "engine/baselines/fixed_step_simulator.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <tuple>

#include "engine/sim/contact_geometry.h"
#include "physics/value_text.h"

namespace baize::engine {
namespace {

using physics::BallState;

// Balls (and a ball and a cushion) this much closer than touching still count as touching, m: the
// event loop's slack for positions rounded in scene files and racks, so a frozen rack is a set of
// touching contacts here as there.
constexpr double kContactSlack_m = 1e-9;
// Resolutions allowed per step for each contact found in it. A frozen cluster needs a few passes
// of sequential impulses (restitution < 1 makes them converge geometrically); a contact still
// approaching after this many is left to the next step rather than looping.
constexpr int kResolutionsPerContact = 64;
// Gauss-Seidel sweeps of the position-only push-out per step; overlap a sweep creates elsewhere is
// found in the next step.
constexpr int kPushOutSweeps = 4;

bool translates(const physics::ClothParams& cloth, const BallState& ball) {
  const physics::MotionState state = physics::motionState(cloth, ball);
  return state == physics::MotionState::Sliding || state == physics::MotionState::Rolling;
}

// A contact found in a step: ball-ball (ball, other), or a ball and cushion or jaw `index`.
struct Contact {
  EventKind kind = EventKind::BallBall;
  int ball = 0;
  int other = -1;
  int index = -1;
};

class FixedStepper {
 public:
  FixedStepper(const SimulationParams& p, const TableGeometry& table, double dt,
               const FixedStepObserver& observer)
      : p_(p), table_(table), dt_(dt), R_(p.ball.radius_m), observer_(observer) {}

  SimulationResult run(const std::vector<BallState>& input);

 private:
  // Unit normal of the contact: from ball to other, or from the cushion or jaw towards the ball.
  Eigen::Vector2d normal(const Contact& c) const {
    const Eigen::Vector2d& q = balls_[c.ball].state.position;
    switch (c.kind) {
      case EventKind::BallBall:
        return (balls_[c.other].state.position - q).normalized();
      case EventKind::Cushion:
        return table_.cushions[c.index].inward_normal;
      default:
        return (q - table_.jaws[c.index].centre_m).normalized();
    }
  }
  // How far the bodies overlap along the normal, m (negative: a gap).
  double depth(const Contact& c) const {
    const Eigen::Vector2d& q = balls_[c.ball].state.position;
    switch (c.kind) {
      case EventKind::BallBall:
        return 2 * R_ - (balls_[c.other].state.position - q).norm();
      case EventKind::Cushion: {
        const CushionSegment& s = table_.cushions[c.index];
        return R_ - s.inward_normal.dot(q - s.start_m);
      }
      default:
        return table_.jaws[c.index].radius_m + R_ - (q - table_.jaws[c.index].centre_m).norm();
    }
  }
  // Speed at which the contact closes, m/s (> 0: approaching).
  double approach(const Contact& c) const {
    const BallState& a = balls_[c.ball].state;
    const Eigen::Vector2d n = normal(c);
    if (c.kind == EventKind::BallBall) {
      const BallState& b = balls_[c.other].state;
      return physics::approachSpeed({a.velocity, a.angular_velocity},
                                    {b.velocity, b.angular_velocity},
                                    Eigen::Vector3d(n.x(), n.y(), 0));
    }
    return -(a.velocity.x() * n.x() + a.velocity.y() * n.y());
  }

  // The contacts of every ball that moved (only those can have reached something new).
  void findContacts();
  // Adds ball i's touching contacts with cushions, jaws and balls not yet scanned.
  void addContactsOf(int i);
  void sortContacts();
  void resolve(const Contact& c);
  void pushOut();
  void record(Event event) {
    if (static_cast<long>(result_.events.size()) >= p_.max_events) {
      throw std::runtime_error(
          "the fixed-step shot recorded more than max_events = " + std::to_string(p_.max_events) +
          " events (at t = " + physics::valueText(now_) + " s)");
    }
    result_.events.push_back(std::move(event));
  }

  const SimulationParams& p_;
  const TableGeometry& table_;
  const double dt_;
  const double R_;
  const FixedStepObserver& observer_;
  double now_ = 0;
  std::vector<BallRecord> balls_;
  std::vector<char> active_;   // moving, or pushed in the last step: may touch something new
  std::vector<char> scanned_;  // ball's contacts are in contacts_
  std::vector<Contact> contacts_;
  SimulationResult result_;
};

void FixedStepper::findContacts() {
  contacts_.clear();
  const int n = static_cast<int>(balls_.size());
  scanned_.assign(n, 0);
  for (int i = 0; i < n; ++i)
    if (active_[i] && !balls_[i].pocketed) addContactsOf(i);
  sortContacts();
}

void FixedStepper::addContactsOf(int i) {
  const int n = static_cast<int>(balls_.size());
  const double touching_m = 2 * R_ + kContactSlack_m;
  const Eigen::Vector2d& q = balls_[i].state.position;
  // Pairs with an already scanned ball are in the list from that ball's scan.
  for (int j = 0; j < n; ++j) {
    if (j == i || balls_[j].pocketed || scanned_[j]) continue;
    if ((balls_[j].state.position - q).squaredNorm() <= touching_m * touching_m)
      contacts_.push_back({EventKind::BallBall, std::min(i, j), std::max(i, j)});
  }
  for (int k = 0; k < static_cast<int>(table_.cushions.size()); ++k) {
    const CushionSegment& s = table_.cushions[k];
    if (R_ - s.inward_normal.dot(q - s.start_m) >= -kContactSlack_m && besideSegment(s, q))
      contacts_.push_back({EventKind::Cushion, i, -1, k});
  }
  for (int k = 0; k < static_cast<int>(table_.jaws.size()); ++k) {
    const JawArc& jaw = table_.jaws[k];
    const double reach_m = jaw.radius_m + R_ + kContactSlack_m;
    if ((q - jaw.centre_m).squaredNorm() <= reach_m * reach_m && onJawArc(jaw, q))
      contacts_.push_back({EventKind::Jaw, i, -1, k});
  }
  scanned_[i] = 1;
}

void FixedStepper::sortContacts() {
  // The event loop's order for simultaneous contacts: by kind (ball-ball, cushion, jaw), then by
  // the balls' and the cushion's numbers.
  std::sort(contacts_.begin(), contacts_.end(), [](const Contact& a, const Contact& b) {
    return std::make_tuple(static_cast<int>(a.kind), a.ball, a.other, a.index) <
           std::make_tuple(static_cast<int>(b.kind), b.ball, b.other, b.index);
  });
}

void FixedStepper::resolve(const Contact& c) {
  Event event{now_, c.kind, c.ball, c.other, c.index, {}, {}};  // the balls are added below
  BallState& a = balls_[c.ball].state;
  const Eigen::Vector2d n = normal(c);
  event.before.push_back(a);
  if (c.kind == EventKind::BallBall) {
    BallState& b = balls_[c.other].state;
    event.before.push_back(b);
    const physics::BallBallImpactResult impact =
        p_.ball_ball->resolve(p_, {a.velocity, a.angular_velocity},
                              {b.velocity, b.angular_velocity}, Eigen::Vector3d(n.x(), n.y(), 0));
    a.velocity = impact.ball1.v;
    a.angular_velocity = impact.ball1.w;
    b.velocity = impact.ball2.v;
    b.angular_velocity = impact.ball2.w;
    event.after = {a, b};
    active_[c.other] = 1;
  } else {
    const ContactFrame frame(n);
    frame.toTable(p_.cushion->resolve(p_, frame.toLocal(a)), &a);
    event.after.push_back(a);
  }
  active_[c.ball] = 1;
  record(std::move(event));
}

void FixedStepper::pushOut() {
  for (int sweep = 0; sweep < kPushOutSweeps; ++sweep) {
    bool moved = false;
    for (const Contact& c : contacts_) {
      const double d = depth(c);
      if (!(d > 0)) continue;
      const Eigen::Vector2d n = normal(c);
      if (c.kind == EventKind::BallBall) {  // equal masses: each ball moves half the overlap
        balls_[c.ball].state.position -= 0.5 * d * n;
        balls_[c.other].state.position += 0.5 * d * n;
        active_[c.other] = 1;
      } else {
        balls_[c.ball].state.position += d * n;
      }
      active_[c.ball] = 1;
      moved = true;
    }
    if (!moved) break;
  }
}

SimulationResult FixedStepper::run(const std::vector<BallState>& input) {
  const int n = static_cast<int>(input.size());
  balls_.resize(n);
  for (int i = 0; i < n; ++i) balls_[i].state = input[i];
  // At the start every ball may already touch something (a frozen rack, a ball on a cushion).
  active_.assign(n, 1);
  for (long step = 0;; ++step) {
    bool any_translates = false;
    for (int i = 0; i < n; ++i) {
      if (balls_[i].pocketed) continue;
      if (translates(p_.cloth, balls_[i].state)) {
        any_translates = true;
        active_[i] = 1;
      }
    }
    now_ = static_cast<double>(step) * dt_;
    if (!any_translates) break;
    if (now_ > kMaxFixedStepShotTime_s) {
      throw std::runtime_error("the fixed-step shot is still moving after " +
                               physics::valueText(kMaxFixedStepShotTime_s) + " s");
    }
    now_ = static_cast<double>(step + 1) * dt_;
    for (int i = 0; i < n; ++i) {
      if (balls_[i].pocketed) continue;
      BallState& b = balls_[i].state;
      const physics::MotionState was = physics::motionState(p_.cloth, b);
      if (was == physics::MotionState::Stationary) continue;
      const BallState before = b;
      b = physics::advance(p_.cloth, b, dt_);
      if (physics::motionState(p_.cloth, b) != was) {
        Event event;
        event.time_s = now_;
        event.ball = i;
        event.before.push_back(before);
        event.after.push_back(b);
        record(std::move(event));
      }
      for (int k = 0; k < static_cast<int>(table_.pockets.size()); ++k) {
        const Circle& pocket = table_.pockets[k];
        if ((b.position - pocket.centre_m).squaredNorm() < pocket.radius_m * pocket.radius_m) {
          balls_[i].pocketed = true;
          Event event;
          event.time_s = now_;
          event.kind = EventKind::Pocket;
          event.ball = i;
          event.index = k;
          event.before.push_back(b);
          event.after.push_back(b);
          record(std::move(event));
          break;
        }
      }
    }
    findContacts();
    // Earliest-begun approaching contact first (the largest overlap per approach speed), so the
    // order of resolutions follows the order in which the contacts would have begun. Contacts that
    // only touch (within the slack) began now: they tie, and the tie goes to the first in the
    // event loop's order (the list is sorted so), as a frozen rack is resolved there.
    for (std::size_t r = 0; r < kResolutionsPerContact * contacts_.size(); ++r) {
      const Contact* earliest = nullptr;
      double earliest_lateness_s = -std::numeric_limits<double>::infinity();
      for (const Contact& c : contacts_) {
        const double speed = approach(c);
        if (!(speed > 0)) continue;
        const double overlap_m = depth(c);
        const double lateness_s = (overlap_m > kContactSlack_m ? overlap_m : 0.0) / speed;
        if (lateness_s > earliest_lateness_s) {
          earliest_lateness_s = lateness_s;
          earliest = &c;
        }
      }
      if (earliest == nullptr) break;
      const Contact resolved = *earliest;
      resolve(resolved);
      // A ball set moving by this impulse (a frozen rack's next ball) may touch balls and
      // cushions that are not in the list yet: at the same instant, as in the event loop.
      bool added = false;
      for (int b : {resolved.ball, resolved.other}) {
        if (b >= 0 && !scanned_[b]) {
          addContactsOf(b);
          added = true;
        }
      }
      if (added) sortContacts();
    }
    // Only balls that moved, were hit or were pushed can touch something new in the next step.
    for (int i = 0; i < n; ++i)
      active_[i] = !balls_[i].pocketed && translates(p_.cloth, balls_[i].state);
    pushOut();
    if (observer_) observer_(now_, balls_);
  }
  // Nothing translates any more, so nothing can touch: the remaining spin about z runs down in
  // closed form in one go, with no steps.
  double end_s = now_;
  for (int i = 0; i < n; ++i) {
    if (balls_[i].pocketed) continue;
    BallState& b = balls_[i].state;
    const double spin_left_s = physics::timeToStateChange(p_.cloth, b);
    if (!std::isfinite(spin_left_s)) continue;
    Event event;
    event.time_s = now_ + spin_left_s;
    event.ball = i;
    event.before.push_back(b);
    b = physics::advance(p_.cloth, b, spin_left_s);
    event.after.push_back(b);
    record(std::move(event));
    end_s = std::max(end_s, event.time_s);
  }
  result_.final_balls = balls_;
  result_.end_time_s = end_s;
  return std::move(result_);
}

void validateFixedStepInput(const SimulationParams& p, const TableGeometry& table,
                            const std::vector<BallState>& balls, double dt) {
  if (!(dt >= kMinFixedTimeStep_s && dt <= kMaxFixedTimeStep_s)) {
    physics::rejectValue("fixed time step (s)", dt,
                         "it must lie in [" + physics::valueText(kMinFixedTimeStep_s) + ", " +
                             physics::valueText(kMaxFixedTimeStep_s) + "]");
  }
  validateSimulationInput(p, table, balls);
}

}  // namespace

SimulationResult simulateFixedStep(const SimulationParams& params, const TableGeometry& table,
                                   const std::vector<BallState>& balls, double time_step_s,
                                   const FixedStepObserver& observer) {
  validateFixedStepInput(params, table, balls, time_step_s);
  return FixedStepper(params, table, time_step_s, observer).run(balls);
}

}  // namespace baize::engine
