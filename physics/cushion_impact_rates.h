// The rates of the exact cushion solver's impact (the Mathavan 2010 model; method at the top of
// cushion_exact_solver.cpp) and its Runge-Kutta step: dz/dtau under the laws in force, written out
// for the common modes (both contacts sliding, one held while the other slides) so that they inline
// into the stages of the generic Dormand-Prince 8(5,3) pair (dop853.h), and the step's error
// measured across the solution's path.
#pragma once

#include "physics/cushion_held_laws.h"
#include "physics/dop853.h"

namespace baize::physics::cushion_exact {

struct Step {
  State z;
  State rate_at_end;  // FSAL: the rate at the step's end, reused as the next step's first stage
  double error = 0;   // scaled error norm; <= 1 accepts
  // (u_I, u_C) at z as slips() gives them, set by finishStep (read only for a main-loop step
  // accepted as it is: a step located or landed on may carry another step's).
  std::array<Eigen::Vector2d, 2> slips_at_end = {Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
};

// The rates and the step on top of the held laws (each method is described where it is defined).
class ImpactRates : public HeldLaws {
 public:
  using HeldLaws::HeldLaws;

  // Whether both contacts slip with friction along their slips (neither held nor approaching):
  // most of every impact, with its own rate (bothSlidingRate).
  bool bothSliding() const {
    return slipping(0) && slipping(1) && !contacts_[0].approaching && !contacts_[1].approaching;
  }
  // Whether the cloth contact is held while the nose slides with friction along its slip: the
  // common held case (a rolling ball's cloth contact), with its own rate (clothHeldRate).
  bool clothHeldWhileNoseSlides() const {
    return held(1) && slipping(0) && !contacts_[0].approaching;
  }
  // Whether the nose contact is held while the cloth slides with friction along its slip.
  bool noseHeldWhileClothSlides() const {
    return held(0) && slipping(1) && !contacts_[1].approaching;
  }

  // dz/dtau at z under the laws in force, and its cases.
  State rate(const State& z);
  State generalRate(const State& z);
  State bothSlidingRate(const State& z);
  State slidingRate(const State& z) const;

  // One Dormand-Prince 8(5,3) step of the impact, and the measure of its error.
  Step rungeKuttaStep(const State& z, const State& k1, double h);
  Step finishStep(const State& z, Step step, State third, State fifth, double h);
  bool slipReversed(const std::array<Eigen::Vector2d, 2>& before,
                    const std::array<Eigen::Vector2d, 2>& after) const;
  double smallSlipGrowthError(const std::array<Eigen::Vector2d, 2>& before,
                              const std::array<Eigen::Vector2d, 2>& after) const;

  long evaluations() const { return evaluations_; }

 protected:
  long evaluations_ = 0;

 private:
  // The size of sliding contact k's slip held in y, its direction (x, y) and the inverse in sigma's
  // factor for it, |u| / (|u| + s0): what the held rates need of the contact that slides. Only the
  // size when it is not positive (the general laws then serve).
  struct SlidingSlip {
    double speed = 0, x = 0, y = 0, inverse = 0;
  };
  [[gnu::always_inline]] inline SlidingSlip slidingSlip(const Extended& y, int k) const;
  [[gnu::always_inline]] inline Extended noseHeldRate(const Extended& y, double vy);
  [[gnu::always_inline]] inline Extended clothHeldRate(const Extended& y, double vy);
  [[gnu::always_inline]] inline Extended bothSlidingRate(const Extended& y, double vy);
  Extended generalExtendedRate(const Extended& y);
  [[gnu::always_inline]] inline Extended scaledRate(double sigma, double ax, double ay, double bx,
                                                    double by, double vy) const;
  // The stages' rates of the written-out cases (defined with them, to inline into the stages).
  struct BothSlidingStage;
  struct ClothHeldStage;
  struct NoseHeldStage;
  template <typename Rate>
  Step extendedStep(const State& z, const State& k1, double h, const Rate& rate);
  template <typename Vector>
  Step finishStep(const State& z, const dop853::Stages<Vector>& stages, double h);
};

}  // namespace baize::physics::cushion_exact
