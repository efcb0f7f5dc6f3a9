// The exact cushion solver's impact equations (the Mathavan 2010 model, docs/cushion.md): the
// state the solver integrates, the slips at the two contacts, the contact matrix and the friction
// each contact law gives. Internal to the exact cushion solver (cushion_exact_solver.cpp explains
// the method); the layers above add the held laws (cushion_held_laws.h), the rates and the
// Runge-Kutta step (cushion_impact_rates.h), step control (cushion_step_control.h) and event
// location (cushion_event_location.h).
#pragma once

#include <Eigen/Core>
#include <array>

#include "physics/cushion_exact_solver.h"
#include "physics/cushion_model.h"

namespace baize::physics::cushion_exact {

using State = Eigen::Matrix<double, 6, 1>;  // (P, A_x, A_y, B_x, B_y: N s; W: J)
enum : int { kP = 0, kAx = 1, kAy = 2, kBx = 3, kBy = 4, kWork = 5, kStateSize = 6 };
// While both contacts slide the Runge-Kutta stages also carry the slips (u_Ix, u_Iy, u_Cx, u_Cy;
// m/s), which are affine in the state: summed with the stages, they reach each stage without the
// contact matrix (see bothSlidingRate).
enum : int { kUIx = kStateSize, kUIy, kUCx, kUCy, kExtendedSize };
using Extended = Eigen::Matrix<double, kExtendedSize, 1>;

// Rounding unit of a double.
constexpr double kEpsilon = 2.220446049250313e-16;

inline double cross(const Eigen::Vector2d& p, const Eigen::Vector2d& q) {
  return p.x() * q.y() - p.y() * q.x();
}

struct ContactState {
  bool frictionless = false;
  ContactMode mode = ContactMode::Slip;  // Stick: held (see the top of cushion_exact_solver.cpp)
  Eigen::Vector2d direction =
      Eigen::Vector2d::UnitX();                      // slip direction for a slip of exactly zero
  Eigen::Vector2d creep = Eigen::Vector2d::UnitX();  // held: where to start looking for phi*
  // Held with a slip that started from zero (not a small slip caught sliding steadily): its slip
  // lags phi*, which turned from creep_origin since then (see lagCorrected).
  bool creep_from_rest = false;
  Eigen::Vector2d creep_origin = Eigen::Vector2d::UnitX();
  // How its slip grows from zero: as the impulse since then (1: held as it vanished, its cone not
  // holding it) or as its square (2: its cone held it until now, so its growth starts at zero).
  double creep_growth_order = 1;
  int small_slip_steps = 0;  // consecutive accepted steps with a slip below kStagnantSlipMultiple
  // m/s: released from its held law with a slip of a tenth of this; taken as sliding steadily
  // along phi* again only once its slip has grown to it (see kSteadyRearmGrowth).
  double steady_rearm_slip = 0;
  // Slipping and approaching zero along its line: runs in P (see kApproachEntry).
  bool approaching = false;
  // Its slip grows away from zero, above kRecedingSlipMultiple x s0: it runs in P (never together
  // with approaching; a slip that large is never held or released directly).
  bool receding = false;
  bool approach_blocked = false;  // left its line: not again until its mode changes
  Eigen::Vector2d approach_direction = Eigen::Vector2d::UnitX();  // its slip's line when it began
};

struct Friction {
  Eigen::Vector2d a = Eigen::Vector2d::Zero();  // at I, per unit P, along the slip
  Eigen::Vector2d b = Eigen::Vector2d::Zero();  // at C, per unit P, along the slip
};

// Per contact: whether its friction follows the stick law, and otherwise its slip direction.
struct Laws {
  std::array<bool, 2> stick = {false, false};
  std::array<Eigen::Vector2d, 2> direction = {Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero()};
};

// The impact's constants, its contacts' states and the equations every contact law shares.
class ImpactEquations {
 public:
  ImpactEquations(const CushionParams& params, const BallVelocity& incoming,
                  const ExactSolverOptions& options);

  bool slipping(int k) const {
    return !contacts_[k].frictionless && contacts_[k].mode == ContactMode::Slip;
  }
  bool held(int k) const {
    return !contacts_[k].frictionless && contacts_[k].mode == ContactMode::Stick;
  }
  // Whether held contact k follows the lag-corrected law (lagCorrected below): held from rest
  // while the other contact slides. Only then is its law accurate beyond a small slip; otherwise
  // (the other contact held too) the slip measured against s0 also ends it.
  bool lagCorrected(int k) const { return contacts_[k].creep_from_rest && !held(1 - k); }
  // Whether slipping contact k's factor |u| / (|u| + s0) is in sigma (not while it approaches or
  // recedes).
  bool regularized(int k) const {
    return slipping(k) && !contacts_[k].approaching && !contacts_[k].receding;
  }
  // The s0 of sliding contact k's factor |u| / (|u| + s0) in sigma: 0 while it recedes (factor 1).
  double factorSlip(int k) const { return contacts_[k].receding ? 0.0 : regularizing_slip_; }

  // The contact matrix (top of cushion_exact_solver.cpp) times (a_x, a_y, b_x, b_y); half its
  // entries are 0.
  Eigen::Vector4d contactResponse(double ax, double ay, double bx, double by) const {
    return {3.5 * ax + coupling_x_ * bx, diagonal_y_ * ay + coupling_y_ * by,
            coupling_x_ * ax + 3.5 * bx, coupling_y_ * ay + 3.5 * by};
  }

  // Both slips at z: (u_I, u_C).
  std::array<Eigen::Vector2d, 2> slips(const State& z) const {
    const Eigen::Vector4d response = contactResponse(z[kAx], z[kAy], z[kBx], z[kBy]);
    return {
        Eigen::Vector2d(slip0_[0] - Eigen::Vector2d(response[0], response[1] - s_ * c_ * z[kP]) *
                                        inverse_mass_),
        Eigen::Vector2d(slip0_[1] -
                        Eigen::Vector2d(response[2], response[3] + c_ * z[kP]) * inverse_mass_)};
  }
  Eigen::Vector2d slip(int k, const State& z) const { return slips(z)[k]; }

  template <typename Vector>  // State, or Extended
  double normalVelocity(const Vector& z) const {
    return vy0_ - (c_ * z[kP] - s_ * z[kAy] + z[kBy]) * inverse_mass_;
  }

  // Friction per unit P under given laws, the slip rates it gives and the cone margins.
  Friction frictionFor(const Laws& laws) const;
  Eigen::Vector2d slipRate(int k, const Friction& f) const;
  double coneMargin(int k, const Friction& f) const;
  std::array<Eigen::Vector2d, 2> slipChanges(const State& r) const;

  // du/dtau = (du_I, du_C) under the rate dz/dtau = (p, ax, ay, bx, by, .) (slipChanges, from the
  // contact matrix scaled as the stages' rate uses it).
  Eigen::Vector4d slipRatesOf(double p, double ax, double ay, double bx, double by) const {
    const ScaledContactMatrix& m = scaled_;
    return {-(m.diagonal_x * ax + m.coupling_x * bx),
            m.sin_cos * p - (m.diagonal_y * ay + m.coupling_y * by),
            -(m.coupling_x * ax + m.diagonal_x * bx),
            -(m.cos * p + (m.coupling_y * ay + m.diagonal_x * by))};
  }

  // z with its slips appended, and a rate with the slips' rates.
  Extended withSlips(const State& z) const {
    const std::array<Eigen::Vector2d, 2> u = slips(z);
    Extended y;
    y << z, u[0], u[1];
    return y;
  }
  Extended withSlipRates(const State& r) const {
    Extended y;
    y << r, slipRatesOf(r[kP], r[kAx], r[kAy], r[kBx], r[kBy]);
    return y;
  }

  // The ball's velocities at z.
  BallVelocity ballAt(const State& z) const;

  const ContactState& contact(int k) const { return contacts_[k]; }

 protected:
  const CushionParams params_;
  const BallVelocity incoming_;
  const double tolerance_;        // ExactSolverOptions::tolerance
  const double min_error_share_;  // ExactSolverOptions::min_error_share
  double s_ = 0, c_ = 0, M_ = 0, inverse_mass_ = 0, vy0_ = 0, velocity_scale_ = 0;
  double impulse_scale_ = 0;  // N s, M V
  double vanished_slip_ = 0;  // m/s, kVanishedSlipFraction
  double regularizing_slip_ =
      0;  // m/s, s0 of the change of variable; also where held contacts slip
  double creep_error_limit_ = 0;  // m/s, kCreepErrorFraction
  std::array<double, 2> mu_;
  std::array<Eigen::Vector2d, 2> slip0_;  // slips at P = 0, shifted by setSlip
  // Entries of the contact matrix M G: [[7/2, 0, cx, 0], [0, s^2 + 5/2, 0, cy], [cx, 0, 7/2, 0],
  // [0, cy, 0, 7/2]] with cx = 1 - 5s/2, cy = 5/2 - s.
  double coupling_x_ = 0, coupling_y_ = 0, diagonal_y_ = 0;
  // The same entries divided by M, and s c / M and c / M, all in 1/kg (slipRatesOf).
  struct ScaledContactMatrix {
    double diagonal_x = 0, diagonal_y = 0, coupling_x = 0, coupling_y = 0, sin_cos = 0, cos = 0;
  } scaled_;
  State error_scale_;
  State inverse_error_scale_;  // 1 / error_scale_, element by element
  std::array<ContactState, 2> contacts_;
};

}  // namespace baize::physics::cushion_exact
