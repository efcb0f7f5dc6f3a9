#include "physics/cushion_exact_solver.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "physics/cushion_event_location.h"
#include "physics/value_text.h"

// How the solver works (the derivation is in docs/cushion-solvers.md).
//
// Write a = -(friction impulse rate at I) in the basis (x, Y') and b = -(friction impulse rate at
// C) in (x, y), both per unit of P. While both contacts slip, a = mu_w (cos Phi, sin Phi) and b =
// mu_s q (cos Phi', sin Phi') with q = sin th + cos th a_y (eq. 8). Every velocity is linear in P
// and in the integrals A = int a dP and B = int b dP (impulseResponse), and so are the slips:
//
//   u_I(P) = u_I(0) - (1/M) [ 7/2 A_x + (1 - 5s/2) B_x ,  (s^2 + 5/2) A_y + (5/2 - s) B_y - s c P ]
//   u_C(P) = u_C(0) - (1/M) [ (1 - 5s/2) A_x + 7/2 B_x ,  c P + (5/2 - s) A_y + 7/2 B_y ]
//
// (s = sin th, c = cos th; the 4x4 matrix is the contacts' inverse effective mass, times M.) So the
// impact is the system y = (A_x, A_y, B_x, B_y, W) with dy/dP = (a, b, c v_y). A stuck contact's
// friction is whatever keeps its slip rate zero (a linear solve), valid while inside its cone.
//
// A slipping contact's friction is along u / |u|, which turns infinitely fast as u -> 0: in P the
// equations are singular there, and steps in P chatter or crawl toward the zero. So the independent
// variable is tau with dP/dtau = sigma = prod over slipping contacts of |u| / (|u| + s0) (leaving
// out a slip that falls along its line or grows well above s0, below). In tau a slip that
// vanishes decays exponentially and one that turns does so smoothly, while a slip far above s0
// runs at sigma ~ 1. When a slip is below the vanishing threshold the contact is held: it
// sticks if its friction cone can hold it; otherwise it slides along the one direction phi* in
// which its slip grows along itself, as long as that law is accurate (an event ends it). A stuck
// contact whose cone stops holding it (an event) slips along the friction it needed, so friction
// stays continuous.
//
// Four special cases cut the cost where the general machinery is slow (docs/cushion-solvers.md,
// "Cost"): the cloth contact's phi* while the nose slides is r0 / |r0| in closed form (its own
// friction enters its slip rate isotropically); a slip growing from rest while the other contact
// slides follows a held law corrected for the lag of its direction behind phi*; a slip falling
// along its own line runs in P with its friction along that line until it vanishes, instead of
// decaying exponentially in tau; and a slip growing well above s0 runs in P too. The rates of the
// common modes (both contacts sliding, or one held while the other slides) are written out and
// inlined into the Runge-Kutta stages, which carry the slips alongside the state.
//
// The system in tau is integrated with the Dormand-Prince 8(5,3) pair, its error measured across
// the path (an error of tau alone moves no state off it), its steps capped at a few time constants
// of the fastest-turning slip direction and at one turning scale |u| / |du/dtau| of each slipping
// slip (beyond either the pair's estimate fails). The ends of compression
// (v_y = 0) and restitution (W = (1 - e^2) W_c, eq. 17b), the instants a stuck contact breaks and
// the end of a held law are events, located by Newton's method (or Illinois regula falsi; a cone
// event from its root along the state's interpolant, then by secants) on the step length, each
// trial a full Runge-Kutta step, and a short last correction one Heun step. The
// phase ends, across which the dynamics do not change, are usually aimed at instead: a step is cut
// to end where they are predicted (extrapolated from the last step) and short third-order steps
// land on them from there.
//
// Where each part lives: the state, slips and friction laws in cushion_impact_equations.h, the
// held laws (phi*, the lag correction, the laws in force) in cushion_held_laws.h, the rates and the
// Runge-Kutta step (on the generic Dormand-Prince 8(5,3) pair of dop853.h) in
// cushion_impact_rates.h, step control in cushion_step_control.h, event location in
// cushion_event_location.h; this file holds the loop and its phases, the contact changes and the
// trace.

namespace baize::physics {
namespace {

using namespace cushion_exact;

// A slipping contact whose slip is at least this multiple of the regularizing slip and growing
// runs in P (its factor in sigma is 1): it moves away from the zero the change of variable guards,
// and its factor's own variation (from about 0.8 toward 1 as it grows) only adds curvature in tau.
// Most such slips are a slip released from rest growing under the other contact's sliding (a ball
// rolling into the cushion): on the impacts of play 7.5 % fewer evaluations (423 to 391 per
// impact) and 2 % fewer on the pool bench's, 1 to 2 % more on the snooker bench's and the spinning
// and grippy sets', the same largest errors; 1, 2 and 10 gave 394, 393 and 399 on the impacts of
// play. Taking out of sigma every slip above it, shrinking ones too, gave 399 at 5 and 416 at 20.
constexpr double kRecedingSlipMultiple = 5;
// A slipping contact whose slip shrinks along its own line runs in P (its factor in sigma is 1)
// with its friction held along that line, as long as the turn its slip rate gives it would carry
// the slip off the line by at most this share of the misalignment limit (kCreepErrorFraction) by
// the time it reaches zero. The slip then falls linearly in P and a step or two reach its zero,
// where in tau (the slip's own factor) the same fall is an exponential decay whose direction mode
// is stiff: about a quarter of an e-fold per step, over the fifteen e-folds from the regularizing
// slip to the vanishing threshold.
constexpr double kApproachEntry = 0.25;
// A contact released from its held law is not taken as sliding steadily along phi* again until
// its slip has grown this many times: just after its release its slip settles near phi* (lagging
// it by less than the held law's limit), is held again at once, and the held law and release
// alternate every few evaluations (found by fuzzing: a thousand contact changes at tolerance
// 1.6e-14, where the limit is tiny).
constexpr double kSteadyRearmGrowth = 10;
// A slipping contact whose slip stays below this multiple of the vanishing threshold for this many
// accepted steps has vanished: it lies within the integration's noise of zero and would only wander
// there (a slip that friction can barely hold decays very slowly). Taking it as zero moves the
// result by less than that multiple of the threshold.
constexpr double kStagnantSlipMultiple = 10;
constexpr int kStagnantSlipSteps = 50;
// A slipping contact whose slip is below this fraction of the regularizing slip is checked for
// steady sliding on the edge of its cone (see slidesSteadily).
constexpr double kSteadyCreepFraction = 0.1;
// A held contact whose cone could hold it again slips on (and its slip shrinks) only once its slip
// is this multiple of the vanishing threshold, so that contacts do not flicker on rounding.
constexpr double kReleaseSlipMultiple = 2;
// The first step after a held contact slips again covers this fraction of the impulse over which
// its small slip's direction turns (|u| / |du/dP|): about what the error control then accepts.
constexpr double kReleaseStepFraction = 0.5;
// An aimed step that does not land (rare: the prediction missed by more than
// kLandingShiftFraction) is followed by at most this many more before phase ends are located with
// trial steps again, until the next event or change (so that aiming never crawls toward the end).
constexpr int kMaxMissedLandings = 2;
// The tolerances accepted: below 1e-14 the slips are not resolved in double precision. Above 1e-6
// the vanishing threshold (kVanishedSlipFraction x tolerance x velocity scale, 5e-6 V at 1e-6)
// comes within about two decades of the regularizing slip (kRegularizingSlipFraction), below which
// slips are resolved: with the threshold at 10 x tolerance x V, at 1e-4 the two met, contacts were
// held and released on every step, and a sixth of random impacts (rolling balls with sidespin) ran
// out of steps or contact changes.
constexpr double kMinTolerance = 1e-14;
constexpr double kMaxTolerance = 1e-6;
// The longest step cap accepted, in time constants of a slip's direction: beyond about 6 a step
// leaves the Dormand-Prince pair's stability region on the real axis, where the slip's direction
// would oscillate instead of settling.
constexpr double kMaxSlipDirectionTimeConstants = 5;
// The other bounds of the step control accepted: the ranges over which the 2,209 impacts of play
// the table leaves (those of the benches' first 3000 random single shots) were solved at the
// default tolerance, at each end and at both ends at once (safety 0.5 and growth 1.5 and a cap of
// 0.5 time constants: 1012 rate evaluations per impact; 1, 5 and 5: 467), the promise kept. Far
// smaller values only multiply the steps toward the step budget.
constexpr double kMinStepSafety = 0.5;
constexpr double kMinStepGrowth = 1.5, kMaxStepGrowth = 5;
constexpr double kMinSlipDirectionTimeConstants = 0.5;
// Logic guards, far above what the bounded equations need (an impact takes tens of steps and a few
// contact changes).
constexpr int kMaxSteps = 100000;
constexpr int kMaxContactChanges = 1000;
// Room for the contact changes of most impacts at once: the two initial modes and up to six changes
// (grown one by one, their reallocations were a sixth of a random shot's allocations).
constexpr std::size_t kContactChangesReserved = 8;

// Where the integration stands between steps.
struct Cursor {
  State z = State::Zero();
  State k1 = State::Zero();  // the rate at z
  double h = 0;              // the next step (tau)
  // The slips at z when an accepted step has just given them (not computed again at the top).
  std::optional<std::array<Eigen::Vector2d, 2>> slips_here;
};

// One step tried from the cursor: aimed at a predicted phase end or not, the events it crossed
// and, once located, where it lands.
struct Attempt {
  double phase_value = 0, phase_slope = 0;  // the phase-end function and its slope at the start
  double proposed_h = 0;                    // the step before any cut to aim
  bool aimed = false;
  Step step;
  FixedList<int, kMaxStepEvents> crossed;  // indices of the events the step crossed
  bool aim_landed = false;                 // landed on the phase end it was aimed at
  int first = -1;                          // the event landed on
  Step landed;
  double length = std::numeric_limits<double>::infinity();  // of the step that lands
};

using StepEvents = FixedList<Event, kMaxStepEvents>;

class ExactImpact : public EventLocation {
 public:
  ExactImpact(const CushionParams& params, const BallVelocity& incoming,
              const ExactSolverOptions& options)
      : EventLocation(params, incoming, options), options_(options) {
    result_.contact_changes.reserve(kContactChangesReserved);
  }

  CushionImpactResult run();

 private:
  Cursor start();
  bool applyDueChanges(const State& z, const std::array<Eigen::Vector2d, 2>& u);
  void restartAfterChanges(Cursor* at);
  void armEvents(Cursor* at, StepEvents* events);
  void attemptStep(Cursor* at, const StepEvents& events, Attempt* attempt);
  void acceptOrShorten(Cursor* at, const Attempt& attempt);
  bool locateCrossed(Cursor* at, const StepEvents& events, Attempt* attempt);
  bool landOnEvents(Cursor* at, const StepEvents& events, const Attempt& attempt);
  bool applyLandedEvents(const State& z, const StepEvents& events, int first, bool* phase_ends);
  bool endPhase(const State& z);

  void setSlip(int k, const State& z, const Eigen::Vector2d& target) {
    slip0_[k] += target - slip(k, z);
  }
  void setMode(int k, ContactMode mode) {
    if (++changes_ > kMaxContactChanges)
      throw std::logic_error("cushion contacts changed state too often");
    contacts_[k].mode = mode;
    contacts_[k].creep_from_rest = false;
    // The cloth's slip from rest grew under the nose's sliding friction; once the nose is held it
    // grows otherwise, and the lag correction's origin no longer stands for it.
    if (mode == ContactMode::Stick) contacts_[1 - k].creep_from_rest = false;
    contacts_[k].approaching = false;
    contacts_[k].approach_blocked = false;
    contacts_[k].receding = false;
  }
  // Records the contacts' physical modes at z where they changed: a contact sticks while it is held
  // and its cone holds it, and slips otherwise (a held contact sliding along phi* slips). Called
  // wherever the laws change: the start, located events, the changes due at a step's end (a slip
  // held where it has vanished, a held contact released). A change of a held law within a step
  // without a located event (a cone holding again near its edge, where its events are not armed)
  // is recorded at that step's end.
  void reportModes(const State& z) {
    Laws laws;  // needed only for a held contact (any other one slips)
    if (held(0) || held(1)) laws = lawsAt(slips(z), nullptr);
    for (int k = 0; k < 2; ++k) {
      if (contacts_[k].frictionless) continue;
      const ContactMode mode = held(k) && laws.stick[k] ? ContactMode::Stick : ContactMode::Slip;
      if (reported_[k] && *reported_[k] == mode) continue;
      reported_[k] = mode;
      result_.contact_changes.push_back({z[kP], k == 0 ? Contact::Cushion : Contact::Cloth, mode});
    }
  }
  // Holds contact k, whose slip has vanished: the leftover (below the vanishing threshold) is
  // removed, and the search for phi* gets a first guess over the whole circle. After an accepted
  // step: counts how long each slipping contact's slip has stayed small.
  void countSmallSlips(const std::array<Eigen::Vector2d, 2>& u) {
    for (int k = 0; k < 2; ++k) {
      const bool small = slipping(k) && u[k].norm() <= kStagnantSlipMultiple * vanished_slip_;
      contacts_[k].small_slip_steps = small ? contacts_[k].small_slip_steps + 1 : 0;
    }
  }
  // Held contact k slips as its own slip says from z on. Its slip is small, so its direction
  // turns over impulses of about |u| / |du/dP|: the next step is cut to that scale instead of
  // being found by rejections from the step the held law could take.
  void release(int k, const State& z) {
    const Eigen::Vector2d u = slip(k, z);
    contacts_[k].direction = u.normalized();
    setMode(k, ContactMode::Slip);
    contacts_[k].steady_rearm_slip = kSteadyRearmGrowth * u.norm();
    const double rate = slipRate(k, frictionFor(lawsAt(slips(z), nullptr))).norm();
    if (rate > 0)
      release_step_cap_ = std::min(release_step_cap_, kReleaseStepFraction * u.norm() / rate);
  }
  void hold(int k, const State& z) {
    contacts_[k].small_slip_steps = 0;
    contacts_[k].steady_rearm_slip = 0;
    const Eigen::Vector2d u = slip(k, z);
    if (u.norm() > 0) contacts_[k].direction = u.normalized();
    setSlip(k, z, Eigen::Vector2d::Zero());
    setMode(k, ContactMode::Stick);
    Laws laws = lawsAt(slips(z), nullptr);
    laws.stick[k] = true;
    contacts_[k].creep = creepDirectionSearch(k, laws);
    contacts_[k].creep_from_rest = true;
    contacts_[k].creep_origin = contacts_[k].creep;
    contacts_[k].creep_growth_order = 1;
  }
  // Which slipping contacts approach zero along their line (see kApproachEntry) and which recede
  // from it (kRecedingSlipMultiple), from the rate dz/dtau at z. When that changes, tau changes
  // meaning: the rate is taken again and the next step h rescaled to cover the same impulse.
  // Returns whether it changed.
  bool updateSlipsRunInP(const State& z, const std::array<Eigen::Vector2d, 2>& u, State* rate_here,
                         double* h) {
    const State& r = *rate_here;
    const std::array<Eigen::Vector2d, 2> change = slipChanges(r);  // du/dtau
    bool changed = false;
    for (int k = 0; k < 2; ++k) {
      ContactState& contact = contacts_[k];
      const double along = u[k].dot(change[k]), across = std::abs(cross(u[k], change[k]));
      // It runs along its line to its zero only if the turn its rate gives it on the way keeps its
      // slip within a share of the misalignment limit of that line (|u| across / -along is the
      // slip that turn builds up off the line by the time it reaches zero).
      const bool approaching = slipping(k) && !contact.approach_blocked && along < 0 &&
                               u[k].norm() * across <= -kApproachEntry * creep_error_limit_ * along;
      const bool receding = slipping(k) && !approaching && along > 0 &&
                            u[k].norm() >= kRecedingSlipMultiple * regularizing_slip_;
      if (receding != contact.receding) {
        contact.receding = receding;
        changed = true;
      }
      if (approaching == contact.approaching) continue;
      contact.approaching = approaching;
      if (approaching) contact.approach_direction = u[k].normalized();
      changed = true;
    }
    if (!changed) return false;
    const double before = r[kP];
    *rate_here = rate(z);
    if (before > 0 && (*rate_here)[kP] > 0) *h *= before / (*rate_here)[kP];
    previous_error_ = 0;
    return true;
  }
  // After an accepted step: held contacts remember where phi* was (the next step's first guess).
  void updateCreepGuesses(const State& z) {
    if (!held(0) && !held(1)) return;
    const Laws laws = lawsAt(slips(z), nullptr);
    for (int k = 0; k < 2; ++k) {
      if (held(k) && !laws.stick[k]) contacts_[k].creep = laws.direction[k];
    }
  }
  void sample(const State& z) {
    ImpactSample s;
    s.impulse_Ns = z[kP];
    s.ball = ballAt(z);
    s.normal_work_J = z[kWork];
    s.cushion_slip = cushionSlip(params_, s.ball);
    s.cloth_slip = clothSlip(params_, s.ball);
    result_.trace.push_back(s);
  }
  // Trace samples inside an accepted step, at every multiple of the spacing in P: each is a
  // Runge-Kutta step of its own from the step's start, as accurate as the step (a cubic through the
  // step's ends finds its length). They do not change the integration.
  void sampleInside(const State& z0, const State& r0, double h, const State& z1, const State& r1) {
    const double spacing = options_.trace_spacing_Ns;
    auto P_at = [&](double t) {
      const double h00 = (1 + 2 * t) * (1 - t) * (1 - t), h10 = t * (1 - t) * (1 - t);
      const double h01 = t * t * (3 - 2 * t), h11 = t * t * (t - 1);
      return h00 * z0[kP] + h10 * h * r0[kP] + h01 * z1[kP] + h11 * h * r1[kP];
    };
    const long evaluations = evaluations_;  // samples are not the solver's cost
    for (double next = (std::floor(z0[kP] / spacing) + 1) * spacing; next < z1[kP];
         next += spacing) {
      double lo = 0, hi = 1;
      for (int it = 0; it < 50; ++it) (P_at(0.5 * (lo + hi)) < next ? lo : hi) = 0.5 * (lo + hi);
      double length = 0.5 * (lo + hi) * h;
      Step sub = rungeKuttaStep(z0, r0, length);
      for (int it = 0; it < 3 && sub.rate_at_end[kP] > 0 && sub.z[kP] != next;
           ++it) {  // Newton on P
        length += (next - sub.z[kP]) / sub.rate_at_end[kP];
        sub = rungeKuttaStep(z0, r0, length);
      }
      sample(sub.z);
    }
    evaluations_ = evaluations;
  }

  const ExactSolverOptions options_;
  int changes_ = 0;
  std::array<std::optional<ContactMode>, 2> reported_;  // the modes recorded last
  CushionImpactResult result_;
};

// The contacts' first modes, and the first step.
Cursor ExactImpact::start() {
  Cursor at;
  for (int k = 0; k < 2; ++k) {
    if (contacts_[k].frictionless) continue;
    const Eigen::Vector2d u = slip(k, at.z);
    if (u.norm() <= vanished_slip_) {
      hold(k, at.z);
    } else {
      contacts_[k].direction = u.normalized();
      setMode(k, ContactMode::Slip);
    }
  }
  reportModes(at.z);
  if (options_.trace_spacing_Ns > 0) sample(at.z);
  at.k1 = rate(at.z);
  at.h = kFirstStepFraction * M_ * vy0_;
  updateSlipsRunInP(at.z, slips(at.z), &at.k1, &at.h);  // a slip may already grow above 5 s0
  return at;
}

// Contact changes due at z (slips u); returns whether any happened. A slip that has decayed below
// the threshold has vanished: the contact is held. A held contact slips as its own slip says once
// that slip is large enough for it (the regularizing slip), or as soon as its cone could hold it
// while it still slips (its slip then shrinks, which the change of variable follows).
bool ExactImpact::applyDueChanges(const State& z, const std::array<Eigen::Vector2d, 2>& u) {
  bool changed = false;
  for (int k = 0; k < 2; ++k) {
    if (slipping(k) &&
        (u[k].norm() <= vanished_slip_ || contacts_[k].small_slip_steps > kStagnantSlipSteps)) {
      hold(k, z);
      changed = true;
    } else if (slipping(k) && u[k].norm() < kSteadyCreepFraction * regularizing_slip_ &&
               u[k].norm() >= contacts_[k].steady_rearm_slip && slidesSteadily(k, u)) {
      setMode(k, ContactMode::Stick);  // its slip stays as it is: it already lies along phi*
      changed = true;
    } else if (held(k) && u[k].norm() > kReleaseSlipMultiple * vanished_slip_) {
      const Laws laws = lawsAt(u, nullptr);
      // While it slides along phi* the true slip lags phi* by an angle that grows with the slip,
      // and the friction along phi* misses that lag: the error shows as the slip's own
      // misalignment with phi*, which bounds how long the held law may run (creepRoom; its end
      // is located loosely, and is due here once within that looseness).
      if (laws.stick[k] || creepRoom(k, z) <= kCreepEndLooseness * creep_error_limit_) {
        release(k, z);
        changed = true;
      }
    }
  }
  return changed;
}

// After contact changes at the cursor: the step trend is broken, the rate taken again, and the
// changes recorded here, where they take effect. (Recorded at the next step's end instead, a stick
// held here was listed late, or not at all when that step ran to where the contact slid again.)
void ExactImpact::restartAfterChanges(Cursor* at) {
  previous_error_ = 0;
  missed_landings_ = 0;
  at->k1 = rate(at->z);
  at->h = std::max(at->h, restartStep(at->k1));
  updateSlipsRunInP(at->z, slips(at->z), &at->k1, &at->h);  // judged again under the new laws
  reportModes(at->z);
}

// The events the next step watches (the phase end first), with the step cut to a held law's
// predicted end and to an approaching slip's zero.
void ExactImpact::armEvents(Cursor* at, StepEvents* events) {
  const State& z = at->z;
  events->push_back(Event{});
  for (int k = 0; k < 2; ++k) {
    if (!held(k)) continue;
    // Armed only clear of the cone's edge, so that an event just applied cannot fire again at
    // once.
    const double margin = neededMargin(k, z);
    const Event candidate{false, k, margin < 0 ? -1.0 : 1.0};
    if (std::abs(margin) > eventTolerance(candidate)) events->push_back(candidate);
    // While it slides along phi* its held law runs only as long as it is accurate: the step
    // must not carry it past that (the error estimate cannot see it, the held law being smooth).
    // Also on the cone's edge (a break just located there), where the cone events are not armed.
    if (margin < eventTolerance(candidate)) {
      events->push_back(Event{false, k, 1.0, true});
      at->h = std::min(at->h, heldLawStep(k, z, at->k1));
    }
  }
  for (int k = 0; k < 2; ++k) {
    if (contacts_[k].approaching) {
      Event approach{false, k, 1.0, false};
      approach.approach_end = true;
      events->push_back(approach);
      Event off{false, k, 1.0, false};
      off.approach_off = true;
      events->push_back(off);
      at->h = std::min(at->h, approachStep(k, z, at->k1));
    }
  }
}

// Tries a step of at->h, aimed at a phase end predicted within it (events[0], extrapolated from
// the last accepted step: landing from there costs a few cheap steps instead of trial steps), and
// lists the events it crossed. Events are judged before the error, which may be large only because
// of what lies beyond them. Every event the step crossed is located, and the step lands on the
// earliest: estimates from the step's ends could order them wrongly (a cone margin is far from
// linear in the step).
void ExactImpact::attemptStep(Cursor* at, const StepEvents& events, Attempt* attempt) {
  attempt->phase_value = eventValue(events[0], at->z);
  attempt->phase_slope = eventSlope(events[0], at->k1);
  attempt->proposed_h = at->h;
  double predicted = 0;
  attempt->aimed = previous_error_ > 0 && missed_landings_ < kMaxMissedLandings &&
                   extrapolatedRoot(last_phase_value_, last_phase_slope_, attempt->phase_value,
                                    attempt->phase_slope, last_step_, at->h, &predicted);
  if (attempt->aimed) at->h = predicted;
  attempt->step = rungeKuttaStep(at->z, at->k1, at->h);
  const Step& step = attempt->step;
  for (int i = 0; i < events.size(); ++i) {
    if (eventValue(events[i], step.z) <= 0) attempt->crossed.push_back(i);
  }
  const FixedList<int, kMaxStepEvents>& crossed = attempt->crossed;
  double shift = 0;
  attempt->aim_landed = attempt->aimed && step.error <= 1 &&
                        (crossed.empty() || (crossed.size() == 1 && crossed[0] == 0)) &&
                        landOnPhaseEnd(step, at->h, &shift, &attempt->landed) &&
                        !crossedOther(events, attempt->landed.z);
  if (attempt->aim_landed) {
    attempt->first = 0;
    attempt->length = at->h + shift;
  } else if (attempt->aimed && step.error <= 1) {
    ++missed_landings_;
  }
}

// A step that crossed no event: accepted when within the tolerance, else the next try shorter.
void ExactImpact::acceptOrShorten(Cursor* at, const Attempt& attempt) {
  const Step& step = attempt.step;
  if (!(step.error <= 1)) {
    at->h *= rejectedStepFactor(step.error);
    return;
  }
  last_phase_value_ = attempt.phase_value;
  last_phase_slope_ = attempt.phase_slope;
  last_step_ = at->h;
  if (options_.trace_spacing_Ns > 0) sampleInside(at->z, at->k1, at->h, step.z, step.rate_at_end);
  at->z = step.z;
  at->k1 = step.rate_at_end;
  updateCreepGuesses(at->z);
  const std::array<Eigen::Vector2d, 2>& u_end = step.slips_at_end;
  at->slips_here = u_end;
  countSmallSlips(u_end);
  // A slip that starts or stops approaching changes the scale of tau: the phase-end function's
  // slope there is no longer comparable with this one's.
  if (updateSlipsRunInP(at->z, u_end, &at->k1, &at->h)) last_step_ = 0;
  reportModes(at->z);
  if (options_.trace_spacing_Ns > 0) sample(at->z);
  const double h = at->h;
  at->h = h * acceptedStepFactor(h, step.error);
}

// Locates every event the step crossed and keeps the earliest. Returns false, with the next step
// shortened, when a located stretch broke the tolerance (a shorter step first).
bool ExactImpact::locateCrossed(Cursor* at, const StepEvents& events, Attempt* attempt) {
  bool retry = false;
  const double step_length = at->h;  // of the step, which every event is located in
  for (int i : attempt->crossed) {
    Step candidate;
    double candidate_length = 0;
    if (!locate(events[i], at->z, at->k1, step_length, attempt->step, &candidate_length,
                &candidate)) {
      at->h = std::min(retry ? at->h : candidate_length, candidate_length);
      retry = true;
      continue;
    }
    if (candidate_length < attempt->length) {
      attempt->length = candidate_length;
      attempt->landed = candidate;
      attempt->first = i;
    }
  }
  return !retry;
}

// Moves the cursor onto the located (or landed) events and applies them; returns whether the
// impact has ended.
bool ExactImpact::landOnEvents(Cursor* at, const StepEvents& events, const Attempt& attempt) {
  const bool tracing = options_.trace_spacing_Ns > 0;
  const Step& landed = attempt.landed;
  if (tracing && attempt.length > 0)
    sampleInside(at->z, at->k1, attempt.length, landed.z, landed.rate_at_end);
  at->z = landed.z;
  const State& z = at->z;
  updateCreepGuesses(z);
  bool phase_ends = false;
  const bool contact_events = applyLandedEvents(z, events, attempt.first, &phase_ends);
  if (attempt.aim_landed && contact_events) {
    previous_error_ = 0;  // the laws changed at the landing: the trend is broken there too
  } else if (attempt.aim_landed) {
    // Only what ends the impact changed, not the dynamics: the trend of the steps before goes on.
    // The proposal was for a step from the aimed step's start (its length after the step's
    // bounds); where the steps shrink, their trend applies once more from the phase end (so the
    // first step after the end of compression is not rejected, as about half of them were, with
    // 1.3 rejections per impact of play within three steps of that end).
    at->h *= std::min(1.0, attempt.proposed_h / previous_step_);  // aimed: previous_step_ > 0
  }
  reportModes(z);
  if (tracing && attempt.length > 0) sample(z);
  at->k1 = rate(z);
  if (contact_events) at->h = std::max(at->h, restartStep(at->k1));
  updateSlipsRunInP(z, slips(z), &at->k1, &at->h);
  return phase_ends && endPhase(z);
}

// Applies the events due at z (the one landed on, and any other within its tolerance); returns
// whether a contact event was among them and sets *phase_ends when the phase ends here.
bool ExactImpact::applyLandedEvents(const State& z, const StepEvents& events, int first,
                                    bool* phase_ends) {
  bool contact_events = false;
  for (int i = 0; i < events.size(); ++i) {
    if (i != first && eventValue(events[i], z) > eventTolerance(events[i])) continue;
    if (events[i].phase_end) {
      *phase_ends = true;
      continue;
    }
    contact_events = true;
    const int k = events[i].contact;
    if (events[i].approach_end) {  // its slip has vanished (what is off its line is within
      hold(k, z);                  // the misalignment limit, which holding it removes)
      continue;
    }
    if (events[i].approach_off) {  // off its line: its friction follows its slip again
      contacts_[k].approaching = false;
      contacts_[k].approach_blocked = true;
      continue;
    }
    if (events[i].creep_end) {  // its held law has run its course: it slips as its slip says
      const Eigen::Vector2d u = slip(k, z);
      if (held(k) && u.norm() > 0) release(k, z);
      continue;
    }
    if (events[i].sign > 0) {  // it slides along phi* from here (reportModes records it)
      contacts_[k].creep_from_rest = false;
      contacts_[k].creep_origin = lawsAt(slips(z), nullptr).direction[k];
      contacts_[k].creep_from_rest = true;
      contacts_[k].creep_growth_order = 2;
      continue;
    }
    // The cone holds the contact again. With a slip left it slides (and its slip shrinks); with
    // none to speak of it sticks.
    const Eigen::Vector2d u = slip(k, z);
    if (u.norm() > kReleaseSlipMultiple * vanished_slip_) {
      contacts_[k].direction = u.normalized();
      setMode(k, ContactMode::Slip);
    }
  }
  return contact_events;
}

// A phase ends at z: restitution follows compression; returns whether the impact has ended.
bool ExactImpact::endPhase(const State& z) {
  if (!compressing_) {
    result_.final_impulse_Ns = z[kP];
    result_.after = ballAt(z);
    return true;
  }
  compressing_ = false;
  last_step_ = 0;  // the last step's phase-end values were of compression's function: none to
                   // extrapolate restitution's from
  result_.compression_impulse_Ns = z[kP];
  result_.compression_work_J = z[kWork];
  compression_work_ = z[kWork];
  work_target_ = (1 - params_.restitution * params_.restitution) * z[kWork];  // eq. 17b
  return false;
}

CushionImpactResult ExactImpact::run() {
  Cursor at = start();
  for (int steps = 0;; ++steps) {
    if (steps == kMaxSteps) throw std::logic_error("exact cushion solver exceeded its step budget");
    const std::array<Eigen::Vector2d, 2> u = at.slips_here ? *at.slips_here : slips(at.z);
    at.slips_here.reset();
    if (applyDueChanges(at.z, u)) {
      restartAfterChanges(&at);
      continue;
    }
    StepEvents events;
    armEvents(&at, &events);
    at.h = cappedStep(u, at.k1, at.h);
    Attempt attempt;
    attemptStep(&at, events, &attempt);
    if (!attempt.aim_landed && attempt.crossed.empty()) {
      acceptOrShorten(&at, attempt);
      continue;
    }
    // An event breaks the step trend, except a phase end landed on where nothing else happens
    // (settled in landOnEvents, once the events due at the landing are known).
    if (!attempt.aim_landed) previous_error_ = 0;
    missed_landings_ = 0;
    // (Landed on the phase end it was aimed at, the only event crossed: nothing to locate.)
    if (!attempt.aim_landed && !locateCrossed(&at, events, &attempt)) continue;
    // The next step goes on as the controller proposed before any cut to aim (as after a located
    // event, which keeps the step that crossed it).
    if (attempt.aimed) at.h = attempt.proposed_h;
    if (landOnEvents(&at, events, attempt)) break;
  }
  result_.rhs_evaluations = evaluations_;
  return std::move(result_);
}

}  // namespace

void validateExactSolverOptions(const ExactSolverOptions& options) {
  if (!(options.tolerance >= kMinTolerance && options.tolerance <= kMaxTolerance)) {
    rejectValue(
        "exact solver tolerance", options.tolerance,
        "it must lie in [" + valueText(kMinTolerance) + ", " + valueText(kMaxTolerance) + "]");
  }
  if (!(options.min_error_share > 0 && options.min_error_share <= 1)) {
    rejectValue("exact solver's smallest error share", options.min_error_share,
                "it must lie in (0, 1]");
  }
  const ExactStepControl& control = options.step_control;
  auto range = [](double low, double high) {
    return "it must lie in [" + valueText(low) + ", " + valueText(high) + "]";
  };
  if (!(control.safety >= kMinStepSafety && control.safety <= 1)) {
    rejectValue("exact solver's step safety factor", control.safety, range(kMinStepSafety, 1));
  }
  if (!(control.max_growth >= kMinStepGrowth && control.max_growth <= kMaxStepGrowth)) {
    rejectValue("exact solver's largest step growth", control.max_growth,
                range(kMinStepGrowth, kMaxStepGrowth));
  }
  if (!(control.slip_direction_time_constants >= kMinSlipDirectionTimeConstants &&
        control.slip_direction_time_constants <= kMaxSlipDirectionTimeConstants)) {
    rejectValue("exact solver's step cap in slip direction time constants",
                control.slip_direction_time_constants,
                range(kMinSlipDirectionTimeConstants, kMaxSlipDirectionTimeConstants));
  }
  if (!(options.trace_spacing_Ns >= 0) || !std::isfinite(options.trace_spacing_Ns)) {
    rejectValue("trace spacing (N s)", options.trace_spacing_Ns, "it must be a finite number >= 0");
  }
}

CushionImpactResult solveCushionImpactExact(const CushionParams& params,
                                            const BallVelocity& incoming,
                                            const ExactSolverOptions& options) {
  validateCushionParams(params);
  validateIncomingBall(incoming);
  validateExactSolverOptions(options);
  const CushionParams at_speed = paramsAtIncidentSpeed(params, incoming);
  return ExactImpact(at_speed, incoming, options).run();
}

}  // namespace baize::physics
