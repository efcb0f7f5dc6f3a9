#include "engine/sim/shot_simulation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "engine/sim/contact_geometry.h"
#include "engine/sim/pressed_contact.h"
#include "engine/sim/simulation_input.h"
#include "physics/polynomial_roots.h"
#include "physics/value_text.h"

namespace baize::engine {
namespace {

using physics::BallState;
using physics::PolynomialCoefficients;

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// Events a result has room for from the start: a random single shot has about eight (grown one
// by one, their reallocations were about a tenth of a random shot's allocations).
constexpr std::size_t kEventsReserved = 16;

// When c0 + c1 t + c2 t^2 (c0 > 0 when apart) first reaches 0, roughly (infinity if never): only
// the order in which cushions are solved, never a result.
double roughClosingTime(const PolynomialCoefficients& gap) {
  const double c0 = gap[0], c1 = gap[1], c2 = gap[2];
  if (!(c0 > 0)) return 0;
  if (c2 == 0) return c1 < 0 ? -c0 / c1 : kInfinity;
  const double discriminant = c1 * c1 - 4 * c2 * c0;
  if (discriminant < 0) return kInfinity;
  const double root = std::sqrt(discriminant);
  const double early = (-c1 - root) / (2 * c2), late = (-c1 + root) / (2 * c2);
  const double first = std::min(early, late), second = std::max(early, late);
  return first >= 0 ? first : (second >= 0 ? second : kInfinity);
}

// Calls visit(k) for each of `boxes` that `reach` overlaps and returns how many it does not (those
// are skipped unsolved). One tight loop over the boxes: a ball's own events look at every cushion,
// jaw and pocket of the table at each of its events, and most are far.
template <class Visit>
long visitOverlapping(const std::vector<Box>& boxes, const Box& reach, Visit visit) {
  const Box* const box = boxes.data();
  const int count = static_cast<int>(boxes.size());
  long missed = 0;
  for (int k = 0; k < count; ++k) {
    if (reach.overlaps(box[k]))
      visit(k);
    else
      ++missed;
  }
  return missed;
}

}  // namespace

ShotSimulation::ShotSimulation(const SimulationParams& params, const TableGeometry& table,
                               const std::vector<BallState>& balls,
                               const std::vector<std::string>& ball_ids,
                               CushionImpactWorker* worker)
    : params_(params), table_(table), ahead_(params, static_cast<int>(balls.size()), worker) {
  validateSimulationInput(params, table, balls, ball_ids);
  ball_ids_ = ball_ids;
  R_ = params.ball.radius_m;
  n_ = static_cast<int>(balls.size());
  result_.events.reserve(kEventsReserved);
  if (params.record_trajectories) {
    result_.trajectories.resize(n_);
    for (int i = 0; i < n_; ++i) result_.trajectories[i].push_back({0, balls[i], false});
  }
  startBalls(balls);
  cushion_boxes_.reserve(table.cushions.size());
  cushion_gaps_.reserve(table.cushions.size());
  jaw_boxes_.reserve(table.jaws.size());
  pocket_boxes_.reserve(table.pockets.size());
  for (const CushionSegment& c : table.cushions)
    cushion_boxes_.push_back(Box::spanning(c.start_m, c.end_m));
  for (const JawArc& jaw : table.jaws)
    jaw_boxes_.push_back(Box::around(jaw.centre_m, jaw.radius_m));
  for (const Circle& pocket : table.pockets)
    pocket_boxes_.push_back(Box::around(pocket.centre_m, pocket.radius_m));

  own_.resize(n_);
  next_of_.resize(n_);
  pair_time_.reset(new double[static_cast<std::size_t>(n_) * n_]);
  partners_.resize(n_);
  listed_.assign(n_, 0);
  is_active_.assign(n_, 0);
  rescanned_.assign(n_, 0);
  std::vector<int> initially_resting;
  for (int i = 0; i < n_; ++i)
    if (!balls_[i].moves) initially_resting.push_back(i);
  resting_grid_ = RestingGrid(initially_resting, balls, R_);
  in_grid_.assign(n_, 0);
  is_resting_later_.assign(n_, 0);
  for (int i : initially_resting) in_grid_[i] = 1;
  on_table_ = n_;
  is_changed_.assign(n_, 0);
  for (int i = 0; i < n_; ++i) {
    if (starts_at_rest_[i]) {
      own_[i] = PredictedEvent{kInfinity, EventKind::StateChange, i};  // what predictOwn() gives
      ++resting_from_start_;
      continue;
    }
    changed_.push_back(i);
    is_changed_[i] = 1;
  }
  // A closed-form rule costs less than handing an impact over.
  solve_ahead_ = params.cushion->worthSolvingAhead();
}

ShotSimulation::~ShotSimulation() = default;

void ShotSimulation::startBalls(const std::vector<BallState>& input) {
  balls_.resize(n_);
  starts_at_rest_.assign(n_, 0);
  for (int i = 0; i < n_; ++i) {
    Track& b = balls_[i];
    b.state = input[i];
    // A ball with no velocity and no spin at all is stationary, never changes state and stays
    // where it is: exactly what settle() would get from the cloth-motion model (whose checks the
    // input has passed), written directly because a crowd of resting balls would otherwise pay for
    // those calls one by one.
    if (b.state.velocity.isZero(0) && b.state.angular_velocity.isZero(0)) {
      starts_at_rest_[i] = 1;
      b.path.constant_m = b.state.position;
      b.box = Box::around(b.state.position, R_);
      continue;
    }
    settle(i, 0);
  }
}

void ShotSimulation::settle(int i, double time_s) {
  Track& b = balls_[i];
  b.reference_time_s = time_s;
  const physics::CurrentMotion motion = physics::currentMotion(params_.cloth, b.state);
  b.motion = motion.state;
  b.change_dt_s = motion.duration_s;
  b.path = motion.path;
  b.moves = motion.state == physics::MotionState::Sliding ||
            motion.state == physics::MotionState::Rolling;
  b.box = b.moves ? sweptBox(b.path, b.change_dt_s, R_) : Box::around(b.state.position, R_);
}

// Ball b's settled state dt_s after its reference time (its motion, found by settle(), is not
// checked again).
BallState ShotSimulation::advanceTrack(const Track& b, double dt_s) const {
  return physics::advanceWithinKnownState(params_.cloth, b.state, b.motion, b.change_dt_s, dt_s);
}

// The path of ball i from time t on (a shift of its quadratic).
physics::PositionQuadratic ShotSimulation::pathFrom(int i, double t) const {
  const Track& b = balls_[i];
  const double s = t - b.reference_time_s;
  if (s == 0) return b.path;
  physics::PositionQuadratic shifted = b.path;
  shifted.constant_m = b.path.at(s);
  shifted.linear_mps = b.path.linear_mps + 2 * s * b.path.quadratic_mps2;
  return shifted;
}

// ---- The public steps ----

std::optional<PredictedEvent> ShotSimulation::nextEvent() {
  prepareNext();
  if (at_rest_) return std::nullopt;
  PredictedEvent next = next_;
  next.dt_s = next_time_s_;
  return next;
}

const Event* ShotSimulation::step() {
  prepareNext();
  if (at_rest_) return nullptr;
  resolveNext();
  return &result_.events.back();
}

void ShotSimulation::advanceTo(double t_s) {
  if (!(t_s >= clock_s_) || std::isnan(t_s))
    physics::rejectValue("time to advance to (s)", t_s,
                         "it must not be before the clock, " + physics::valueText(clock_s_) + " s");
  for (;;) {
    prepareNext();
    if (at_rest_ || next_time_s_ > t_s) break;
    resolveNext();
  }
  clock_s_ = t_s;
}

SimulationResult ShotSimulation::runToRest() {
  for (;;) {
    prepareNext();
    if (at_rest_) break;
    resolveNext();
  }
  return finish();
}

BallState ShotSimulation::ballAt(int i) const {
  const Track& b = balls_[i];
  if (b.pocketed || !(clock_s_ > b.reference_time_s)) return b.state;
  return physics::advance(params_.cloth, b.state, clock_s_ - b.reference_time_s);
}

// ---- Predicting ----

// Finds the next event if the last one's changes are not predicted yet: a pass over the balls that
// changed, then the earliest candidate. A stale prediction (a state change of a ball that has none
// ahead) only asks for another pass.
void ShotSimulation::prepareNext() {
  while (prediction_due_) {
    if (passes_ == params_.max_events) {
      throw std::runtime_error("the shot did not come to rest within max_events = " +
                               std::to_string(params_.max_events) +
                               " events (at t = " + physics::valueText(now_) + " s)");
    }
    ++passes_;
    predictChanged();
    next_ = earliest();
    if (!(next_.dt_s < kInfinity)) {  // every ball at rest or pocketed
      at_rest_ = true;
      prediction_due_ = false;
      return;
    }
    next_time_s_ = std::max(next_.dt_s, now_);  // rounding of absolute times
    for (int i : changed_) is_changed_[i] = 0;
    changed_.clear();
    if (next_.kind == EventKind::StateChange && !(balls_[next_.ball].change_dt_s < kInfinity)) {
      markChanged(next_.ball);  // a stale prediction: predict it again
      continue;
    }
    prediction_due_ = false;
  }
}

// Predicts again what involves a ball that changed; each other ball's earliest candidate is then
// updated with its new pairs, or found again if it was one of the stale ones.
void ShotSimulation::predictChanged() {
  forgetPairsOfChanged();
  predictOwnOfChanged();  // own events first: a pair is predicted only as far as both paths hold
  updateActiveBalls();
  predictPairsOfChanged();
  first_pass_ = false;
  refreshEarliest();
  handOverImpacts();
}

// Every pair of a changed ball is predicted again (or left empty): clear the old ones.
void ShotSimulation::forgetPairsOfChanged() {
  for (int i : changed_) {
    for (int j : partners_[i]) pairTime(i, j) = kInfinity;
    partners_[i].clear();
  }
}

void ShotSimulation::predictOwnOfChanged() {
  for (int i : changed_) {
    if (!balls_[i].pocketed) {
      predictOwn(i);
      continue;
    }
    own_[i] = PredictedEvent{};
    ahead_.forget(i);
  }
}

void ShotSimulation::updateActiveBalls() {
  for (int i : changed_) {
    const bool now_active = !balls_[i].pocketed && (balls_[i].moves || own_[i].dt_s < kInfinity);
    if (now_active != static_cast<bool>(is_active_[i])) {
      is_active_[i] = now_active;
      if (now_active)
        active_.push_back(i);
      else
        active_.erase(std::find(active_.begin(), active_.end(), i));
    }
    if (first_pass_) continue;
    // Its place in the grid no longer holds; at rest, it is looked at one by one.
    in_grid_[i] = 0;
    if (!balls_[i].moves && !balls_[i].pocketed && !is_resting_later_[i]) {
      is_resting_later_[i] = 1;
      resting_later_.push_back(i);
    }
  }
  movers_.clear();
  for (int k : active_)
    if (balls_[k].moves) movers_.push_back(k);
}

void ShotSimulation::predictPairsOfChanged() {
  // A pair of two changed balls is predicted once, by the lower-numbered one (or, in the first
  // pass, by the moving one).
  self_predicting_.clear();
  for (int i : changed_)
    if (!balls_[i].pocketed && !(first_pass_ && !balls_[i].moves)) self_predicting_.push_back(i);
  std::sort(self_predicting_.begin(), self_predicting_.end());
  long resting = 0;  // first pass: balls at rest, whose pairs are skipped
  for (int i : changed_) {
    if (balls_[i].pocketed) continue;
    if (first_pass_ && !balls_[i].moves) {  // its pairs with resting balls: already empty
      ++resting;
      continue;
    }
    predictPairsOf(i);
  }
  if (first_pass_) {
    resting += resting_from_start_;
    result_.skipped_predictions += resting * (resting - 1) / 2;
  }
}

// Ball i's pairs: with every ball that moves, and, if it moves, with the resting balls its swept
// box reaches. Every other ball on the table is a pair predictPair() would skip (both at rest, or
// boxes apart), counted as such.
void ShotSimulation::predictPairsOf(int i) {
  long visited = 0;
  auto visit = [&](int j) {
    predictPair(i, j);
    ++visited;
  };
  for (int j : movers_)
    if (j != i && !(j < i && is_changed_[j])) visit(j);
  if (balls_[i].moves) {
    auto visitResting = [&](int j) {
      if (balls_[j].moves || balls_[j].pocketed || !balls_[j].box.overlaps(balls_[i].box)) return;
      if (j < i && is_changed_[j] && !first_pass_) return;
      visit(j);
    };
    resting_grid_.forEachNear(balls_[i].box, R_ + kBoxMargin_m, [&](int j) {
      if (in_grid_[j]) visitResting(j);
    });
    for (int j : resting_later_) visitResting(j);
  }
  const long predicted_elsewhere =
      std::lower_bound(self_predicting_.begin(), self_predicting_.end(), i) -
      self_predicting_.begin();
  result_.skipped_predictions += (on_table_ - 1) - predicted_elsewhere - visited;
}

void ShotSimulation::refreshEarliest() {
  for (int k : active_) {
    rescanned_[k] =
        is_changed_[k] || (next_of_[k].dt_s < kInfinity &&
                           (is_changed_[next_of_[k].ball] ||
                            (next_of_[k].other >= 0 && is_changed_[next_of_[k].other])));
    if (rescanned_[k]) rescan(k);
  }
  // The others gain the changed balls' new pairs (their finite ones: all in partners_ now).
  for (int i : changed_) {
    for (int k : partners_[i]) {
      if (!is_active_[k] || rescanned_[k]) continue;
      const PredictedEvent c = pairCandidate(k, i);
      if (c.dt_s < kInfinity && c < next_of_[k]) {
        next_of_[k] = c;
        ahead_.forget(k);  // its contact, if one was handed over, now comes after this pair's
      }
    }
  }
}

// A ball whose earliest event is now a cushion or jaw contact has it solved ahead, while other
// balls move too (a lone ball's next events are its own: nothing to overlap with).
void ShotSimulation::handOverImpacts() {
  if (!solve_ahead_ || !ahead_.mayUse()) return;
  for (int k : active_) {
    if (!rescanned_[k]) continue;
    if (movers_.size() >= 2)
      solveAhead(k);
    else
      ahead_.forget(k);
  }
}

PredictedEvent ShotSimulation::earliest() const {
  PredictedEvent best;
  for (int k : active_)
    if (next_of_[k].dt_s < kInfinity && next_of_[k] < best) best = next_of_[k];
  return best;
}

// The first closing root of a gap polynomial in [0, horizon]; a gap the cheap bounds show to stay
// open, or (touching now: a contact just resolved) to open throughout, is counted as skipped
// instead of solved.
physics::RootSearchResult ShotSimulation::solveGap(const PolynomialCoefficients& gap,
                                                   double horizon) {
  if (staysApart(gap, horizon) || (!(gap[0] > 0) && opensThroughout(gap, horizon))) {
    ++result_.skipped_predictions;
    return physics::RootSearchResult{};
  }
  ++result_.predictions;
  return physics::firstClosingRoot(gap, 0, horizon);
}

// A prediction made now: dt from now, stored as an absolute time (the just-resolved contact is not
// found again at the same instant).
PredictedEvent ShotSimulation::absolute(PredictedEvent c) const {
  if (last_valid_ && c.dt_s == 0 && c.sameContact(last_)) c.dt_s = kInfinity;
  c.dt_s += now_;
  return c;
}

double& ShotSimulation::pairTime(int i, int j) {
  return pair_time_[static_cast<std::size_t>(std::min(i, j)) * n_ + std::max(i, j)];
}

PredictedEvent ShotSimulation::pairCandidate(int i, int j) const {
  if (i > j) std::swap(i, j);
  return PredictedEvent{pair_time_[static_cast<std::size_t>(i) * n_ + j], EventKind::BallBall, i,
                        j};
}

// Impacts solved ahead (engine/sim/cushion_solve_ahead.h): ball i's earliest event, if it is a
// cushion or jaw contact, from the state the ball will have then, as moveToEvent() will find it.
void ShotSimulation::solveAhead(int i) {
  const PredictedEvent& c = next_of_[i];
  if (!(c.dt_s < kInfinity) || (c.kind != EventKind::Cushion && c.kind != EventKind::Jaw)) {
    ahead_.forget(i);
    return;
  }
  const Track& b = balls_[i];
  BallState at = b.state;
  const double dt = std::min(c.dt_s - b.reference_time_s, b.change_dt_s);
  if (dt > 0) at = advanceTrack(b, dt);
  const physics::BallVelocity local =
      ContactFrame(contactNormal(table_, c.kind, c.index, at.position)).toLocal(at);
  if (local.v.y() > 0)
    ahead_.predict(i, c.dt_s, local);
  else
    ahead_.forget(i);
}

// Ball i was settled at now_. Its motion changes at its first own event: nothing after it needs
// predicting, so the horizon and the swept box shrink to it as events are found (cushions first:
// cheap).
void ShotSimulation::predictOwn(int i) {
  Track& b = balls_[i];
  PredictedEvent best_own{b.change_dt_s, EventKind::StateChange, i};
  double horizon = b.change_dt_s;
  if (b.moves) {
    predictCushions(i, &horizon, &best_own);
    predictJaws(i, &horizon, &best_own);
    predictPockets(i, &horizon, &best_own);
  }
  b.valid_until_s = now_ + horizon;
  own_[i] = absolute(best_own);
}

// The cushions whose box the ball's reaches are solved nearest first (by a rough estimate of when
// the gap closes): a cushion whose gap stays open until the best event found so far, or whose box
// the ball's box until then does not reach, cannot be the ball's first and is skipped unsolved
// (the box check drops the cushion on the same line as the one just hit, beyond a pocket). Only
// the order of the work changes, not what is found.
void ShotSimulation::predictCushions(int i, double* horizon, PredictedEvent* best_own) {
  Track& b = balls_[i];
  const physics::PositionQuadratic& path = b.path;
  cushion_gaps_.clear();
  const long boxes_apart = visitOverlapping(cushion_boxes_, b.box, [&](int k) {
    const CushionSegment& c = table_.cushions[k];
    const PolynomialCoefficients gap = {c.inward_normal.dot(path.constant_m - c.start_m) - R_,
                                        c.inward_normal.dot(path.linear_mps),
                                        c.inward_normal.dot(path.quadratic_mps2), 0, 0};
    cushion_gaps_.push_back({roughClosingTime(gap), k, gap});
  });
  result_.skipped_predictions += boxes_apart;
  std::sort(cushion_gaps_.begin(), cushion_gaps_.end(),
            [](const CushionGap& a, const CushionGap& b) {
              return a.rough_time_s < b.rough_time_s ||
                     (a.rough_time_s == b.rough_time_s && a.cushion < b.cushion);
            });
  Box reach = b.box;  // swept until the best event found so far
  for (const CushionGap& g : cushion_gaps_) {
    if (quadraticStaysAbove(g.gap, best_own->dt_s) || !reach.overlaps(cushion_boxes_[g.cushion])) {
      ++result_.skipped_predictions;
      continue;
    }
    const physics::RootSearchResult hit = solveGap(g.gap, *horizon);
    if (hit.outcome != physics::RootOutcome::Root) continue;
    const CushionSegment& c = table_.cushions[g.cushion];
    const Eigen::Vector2d along = c.end_m - c.start_m;
    const double s = (path.at(hit.time) - c.start_m).dot(along) / along.squaredNorm();
    const PredictedEvent candidate{hit.time, EventKind::Cushion, i, -1, g.cushion};
    if (s >= 0 && s <= 1 && absolute(candidate).dt_s < kInfinity && candidate < *best_own) {
      *best_own = candidate;
      reach = sweptBox(path, best_own->dt_s, R_);
    }
  }
  *horizon = best_own->dt_s;
  b.box = sweptBox(path, *horizon, R_);
}

void ShotSimulation::predictJaws(int i, double* horizon, PredictedEvent* best_own) {
  Track& b = balls_[i];
  const physics::PositionQuadratic& path = b.path;
  const long boxes_apart = visitOverlapping(jaw_boxes_, b.box, [&](int k) {
    const JawArc& jaw = table_.jaws[k];
    if (staysFarther(path.constant_m - jaw.centre_m, path.linear_mps, path.quadratic_mps2,
                     jaw.radius_m + R_, best_own->dt_s)) {  // not before the best so far
      ++result_.skipped_predictions;
      return;
    }
    const PolynomialCoefficients gap = squaredGap(path, jaw.centre_m, Eigen::Vector2d::Zero(),
                                                  Eigen::Vector2d::Zero(), jaw.radius_m + R_);
    const physics::RootSearchResult hit = solveGap(gap, *horizon);
    const PredictedEvent candidate{hit.time, EventKind::Jaw, i, -1, k};
    if (hit.outcome == physics::RootOutcome::Root && onJawArc(jaw, path.at(hit.time)) &&
        absolute(candidate).dt_s < kInfinity && candidate < *best_own) {
      *best_own = candidate;
    }
  });
  result_.skipped_predictions += boxes_apart;
  *horizon = best_own->dt_s;
  b.box = sweptBox(path, *horizon, R_);
}

void ShotSimulation::predictPockets(int i, double* horizon, PredictedEvent* best_own) {
  Track& b = balls_[i];
  const physics::PositionQuadratic& path = b.path;
  const long boxes_apart = visitOverlapping(pocket_boxes_, b.box, [&](int k) {
    const Circle& pocket = table_.pockets[k];
    if (staysFarther(path.constant_m - pocket.centre_m, path.linear_mps, path.quadratic_mps2,
                     pocket.radius_m, best_own->dt_s)) {  // not before the best so far
      ++result_.skipped_predictions;
      return;
    }
    const PolynomialCoefficients gap = squaredGap(path, pocket.centre_m, Eigen::Vector2d::Zero(),
                                                  Eigen::Vector2d::Zero(), pocket.radius_m);
    const physics::RootSearchResult hit = solveGap(gap, *horizon);
    const PredictedEvent candidate{hit.time, EventKind::Pocket, i, -1, k};
    if (hit.outcome == physics::RootOutcome::Root && candidate < *best_own) *best_own = candidate;
  });
  result_.skipped_predictions += boxes_apart;
  *horizon = best_own->dt_s;
  b.box = sweptBox(path, *horizon, R_);
}

// When balls i and j touch, i settled at now_.
void ShotSimulation::predictPair(int i, int j) {
  double& cached = pairTime(i, j);
  cached = kInfinity;
  const Track &bi = balls_[i], &bj = balls_[j];
  if (bj.pocketed) return;
  if (!bi.moves && !bj.moves) {
    ++result_.skipped_predictions;
    return;
  }
  // Cheap bound first: the boxes the two sweep until either changes state do not meet.
  if (!bi.box.overlaps(bj.box)) {
    ++result_.skipped_predictions;
    return;
  }
  const double horizon = std::min(bi.moves ? bi.valid_until_s - now_ : kInfinity,
                                  bj.moves ? bj.valid_until_s - now_ : kInfinity);
  const physics::PositionQuadratic path_i = bi.path, path_j = pathFrom(j, now_);
  const int a = std::min(i, j), b = std::max(i, j);  // the gap of the lower-numbered ball
  const physics::PositionQuadratic& pa = a == i ? path_i : path_j;
  const physics::PositionQuadratic& pb = a == i ? path_j : path_i;
  if (staysFarther(pa.constant_m - pb.constant_m, pa.linear_mps - pb.linear_mps,
                   pa.quadratic_mps2 - pb.quadratic_mps2, 2 * R_, std::max(0.0, horizon))) {
    ++result_.skipped_predictions;
    return;
  }
  const PolynomialCoefficients gap =
      squaredGap(pa, pb.constant_m, pb.linear_mps, pb.quadratic_mps2, 2 * R_);
  const physics::RootSearchResult hit = solveGap(gap, std::max(0.0, horizon));
  if (hit.outcome == physics::RootOutcome::Root)
    cached = absolute({hit.time, EventKind::BallBall, a, b}).dt_s;
  if (cached < kInfinity) {
    partners_[a].push_back(b);
    partners_[b].push_back(a);
  }
}

// Ball k's earliest candidate, from scratch. Its list of partners is cleaned on the way (pairs
// since predicted empty and repeats dropped), so that it cannot grow with every event of a
// neighbour while ball k itself has none.
void ShotSimulation::rescan(int k) {
  PredictedEvent best = own_[k];
  std::vector<int>& list = partners_[k];
  std::size_t kept = 0;
  for (std::size_t m = 0; m < list.size(); ++m) {
    const int j = list[m];
    const PredictedEvent c = pairCandidate(k, j);
    if (!(c.dt_s < kInfinity) || listed_[j]) continue;
    listed_[j] = 1;
    list[kept++] = j;
    if (c < best) best = c;
  }
  list.resize(kept);
  for (int j : list) listed_[j] = 0;
  next_of_[k] = best;
}

// ---- Resolving ----

void ShotSimulation::resolveNext() {
  const PredictedEvent& best = next_;
  moveToEvent(best.ball);
  if (best.kind == EventKind::BallBall) moveToEvent(best.other);
  now_ = next_time_s_;
  clock_s_ = std::max(clock_s_, now_);
  last_ = best;
  last_valid_ = true;

  Event event{now_, best.kind, best.ball, best.other, best.index, {}, {}};  // balls below
  event.before.push_back(balls_[best.ball].state);
  if (best.kind == EventKind::BallBall) event.before.push_back(balls_[best.other].state);
  switch (best.kind) {
    case EventKind::StateChange:
      break;  // advanceWithinState set the next state exactly
    case EventKind::Pocket:
      balls_[best.ball].pocketed = true;
      balls_[best.ball].pocket = best.index;
      --on_table_;
      break;
    case EventKind::Cushion:
    case EventKind::Jaw:
      resolveCushionContact(&event);
      break;
    case EventKind::BallBall:
      resolveBallContact(&event);
      break;
  }
  finishEvent(std::move(event));
  prediction_due_ = true;
}

// Moves ball i to the next event's instant. A state change happens exactly at the ball's
// transition time, where advanceWithinState sets the next state exactly.
void ShotSimulation::moveToEvent(int i) {
  Track& b = balls_[i];
  const double dt = next_.kind == EventKind::StateChange
                        ? b.change_dt_s
                        : std::min(next_time_s_ - b.reference_time_s, b.change_dt_s);
  if (dt > 0) b.state = advanceTrack(b, dt);
}

// The chosen cushion model (engine/sim/cushion_contact_model.h) in the frame of the contact normal,
// or the worker's answer from the same input.
void ShotSimulation::resolveCushionContact(Event* event) {
  Track& ball = balls_[event->ball];
  BallState& a = ball.state;
  const Eigen::Vector2d normal = contactNormal(table_, event->kind, event->index, a.position);
  const ContactFrame frame(normal);
  const physics::BallVelocity local = frame.toLocal(a);
  const bool pressed = ball.path.quadratic_mps2.dot(normal) < 0;
  if (!(local.v.y() > 0 || pressed)) return;
  physics::BallVelocity after = local;
  if (local.v.y() > 0) after = ahead_.resolve(event->ball, local);
  // In the cushion's frame the normal into the table is -y.
  if (pressed)
    releasePressedContact(params_.ball, kineticEnergy(params_.ball, local),
                          Eigen::Vector3d(0, -1, 0), &after, nullptr);
  frame.toTable(after, &a);
}

void ShotSimulation::resolveBallContact(Event* event) {
  BallState& a = balls_[event->ball].state;
  BallState& b = balls_[event->other].state;
  Eigen::Vector3d normal(b.position.x() - a.position.x(), b.position.y() - a.position.y(), 0);
  normal.normalize();
  const physics::BallVelocity va{a.velocity, a.angular_velocity},
      vb{b.velocity, b.angular_velocity};
  const bool approaching = physics::approachSpeed(va, vb, normal) > 0;
  const bool pressed =
      (balls_[event->ball].path.quadratic_mps2 - balls_[event->other].path.quadratic_mps2)
          .dot(normal.head<2>()) > 0;
  if (!(approaching || pressed)) return;
  physics::BallVelocity a_after = va, b_after = vb;
  if (approaching) {
    const physics::BallBallImpactResult impact =
        params_.ball_ball->resolve(params_, va, vb, normal);
    a_after = impact.ball1;
    b_after = impact.ball2;
  }
  if (pressed) {
    releasePressedContact(params_.ball,
                          kineticEnergy(params_.ball, va) + kineticEnergy(params_.ball, vb), normal,
                          &a_after, &b_after);
  }
  a.velocity = a_after.v;
  a.angular_velocity = a_after.w;
  b.velocity = b_after.v;
  b.angular_velocity = b_after.w;
}

// Records the event, settles its balls on their new motion and checks they are on the table.
void ShotSimulation::finishEvent(Event&& event) {
  const int ball = event.ball, other = event.other;
  const bool two = event.kind == EventKind::BallBall;
  const BallState& a = balls_[ball].state;
  event.after.push_back(a);
  if (two) event.after.push_back(balls_[other].state);
  markChanged(ball);
  settle(ball, now_);
  if (two) {
    markChanged(other);
    settle(other, now_);
  }
  // Every ball that moves ends its motion at an event of its own, so checking the balls of each
  // event finds any that left (one point-in-polygon test per ball per event).
  if (!table_.outline.empty()) {
    requireOnTable(table_, event, ball, balls_[ball].pocketed, a, ball_ids_);
    if (two) requireOnTable(table_, event, other, false, balls_[other].state, ball_ids_);
  }
  if (params_.record_trajectories && event.kind != EventKind::StateChange) {
    // (a state change is in closed form)
    result_.trajectories[ball].push_back({now_, a, balls_[ball].pocketed});
    if (two) result_.trajectories[other].push_back({now_, balls_[other].state, false});
  }
  result_.events.push_back(std::move(event));
}

void ShotSimulation::markChanged(int i) {
  changed_.push_back(i);
  is_changed_[i] = 1;
}

// Balls at rest are reported exactly at rest (a speed below the at-rest threshold, left by a
// transition a rounding early, is not motion).
SimulationResult ShotSimulation::finish() {
  result_.final_balls.resize(n_);
  for (int i = 0; i < n_; ++i) {
    result_.final_balls[i].pocketed = balls_[i].pocketed;
    result_.final_balls[i].pocket = balls_[i].pocket;
    const BallState& b = balls_[i].state;
    const bool exactly_at_rest = b.velocity.isZero(0) && b.angular_velocity.isZero(0);
    result_.final_balls[i].state = balls_[i].pocketed || exactly_at_rest
                                       ? b
                                       : physics::advanceWithinState(params_.cloth, b, 0);
  }
  result_.end_time_s = now_;
  return std::move(result_);
}

}  // namespace baize::engine
