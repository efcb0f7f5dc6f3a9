#include "physics/cushion_impact_rates.h"

#include <algorithm>
#include <cmath>

namespace baize::physics::cushion_exact {

// A slipping slip below the regularizing slip that grows may change by at most this multiple of its
// own size in one step (so grow by at most 70 %, and turn by at most about 41 degrees). Near a slip
// that small (a nose slip growing again after passing close by zero) a longer step comes near the
// branch point of |u| for complex impulses, where the embedded error estimate fails: measured 5 to
// 30 times below the step's true error. Such steps made the largest errors of the bench's impacts
// on the pool cushion (at tolerance 3e-11: 9.0e-10 V0, 5.4e-10 with a bound of 1) and, with a bound
// of 1, of the impacts of play (1.1e-9 V0 over the 16,180 of `baize bench cushion --from-shots
// 5000` as the shots were then, a slip growing from 4.1e-4 to 7.7e-4 V in one step; 5.9e-10 with
// 0.7, for 1 % more evaluations there and 0.3 to 0.6 % on the bench's).
constexpr double kSmallSlipGrowthPerStep = 0.7;

// dz/dtau.
State ImpactRates::rate(const State& z) {
  if (bothSliding()) return bothSlidingRate(z);
  if (clothHeldWhileNoseSlides())
    return clothHeldRate(withSlips(z), normalVelocity(z)).head<kStateSize>();
  if (noseHeldWhileClothSlides())
    return noseHeldRate(withSlips(z), normalVelocity(z)).head<kStateSize>();
  return generalRate(z);
}

// rate() under the general laws (lawsAt).
State ImpactRates::generalRate(const State& z) {
  ++evaluations_;
  if (!held(0) && !held(1)) return slidingRate(z);
  std::array<double, 2> speed;
  const Laws laws = lawsAt(slips(z), &speed);
  const Friction f = frictionFor(laws);
  double sigma = 1;  // dP/dtau
  for (int k = 0; k < 2; ++k) {
    if (regularized(k)) sigma *= speed[k] / (speed[k] + regularizing_slip_);
  }
  State r;
  r << 1, f.a.x(), f.a.y(), f.b.x(), f.b.y(), c_ * normalVelocity(z);
  return sigma * r;
}

// rate() while the nose is held and the cloth slides (noseHeldWhileClothSlides), at the slips
// held in y: the general laws written out for this case. The nose sticks while its stick law's
// friction lies inside its cone (compared squared), and otherwise slides along phi*, found by
// Newton's method on its slip rate, which is affine in its direction d: r(d) = r0 + W d with,
// per unit P and the cloth's friction mu_s (s + c mu_w d_y) along d_C,
//   r0 = -(1/M) ((1 - 5s/2) mu_s s d_Cx, (5/2 - s) mu_s s d_Cy - s c),
//   W = -(mu_w/M) [7/2, (1 - 5s/2) mu_s c d_Cx; 0, s^2 + 5/2 + (5/2 - s) mu_s c d_Cy];
// lag-corrected as lagShare says. The general laws serve an exactly zero cloth slip and a phi*
// that Newton does not find.
[[gnu::always_inline]] inline Extended ImpactRates::noseHeldRate(const Extended& y, double vy) {
  const SlidingSlip cloth_slip = slidingSlip(y, 1);
  if (!(cloth_slip.speed > 0)) return generalExtendedRate(y);
  const double speed_C = cloth_slip.speed, inverse = cloth_slip.inverse;
  const double dCx = cloth_slip.x, dCy = cloth_slip.y;
  // The nose's stick law under the sliding cloth (frictionFor).
  const double gx = mu_[1] * dCx, gy = mu_[1] * dCy;
  double ay = (s_ * c_ - coupling_y_ * s_ * gy) / (diagonal_y_ + coupling_y_ * c_ * gy);
  double ax = -coupling_x_ * (s_ + c_ * ay) * gx * (1 / 3.5);
  const double hold_limit = mu_[0] * (1 - kConeSlackRelative);
  if (!(ax * ax + ay * ay <= hold_limit * hold_limit)) {
    const double nose = mu_[0] * inverse_mass_, cloth = mu_[1] * inverse_mass_;
    const Eigen::Vector2d r0(-coupling_x_ * cloth * s_ * dCx,
                             -(coupling_y_ * cloth * s_ * dCy - s_ * c_ * inverse_mass_));
    Eigen::Matrix2d W;
    W << -3.5 * nose, -coupling_x_ * cloth * c_ * mu_[0] * dCx, 0,
        -(diagonal_y_ * nose + coupling_y_ * cloth * c_ * mu_[0] * dCy);
    Eigen::Vector2d phi;
    if (!affineNewton(r0, W, contacts_[0].creep, &phi)) return generalExtendedRate(y);
    if (lagCorrected(0)) {
      phi = lagCorrected(contacts_[0].creep_origin, phi,
                         affineLagShare(r0, W, phi, contacts_[0].creep_growth_order));
    }
    ax = mu_[0] * phi.x();
    ay = mu_[0] * phi.y();
  }
  ++evaluations_;
  const double limit = mu_[1] * (s_ + c_ * ay);
  return scaledRate(speed_C * inverse, ax, ay, limit * dCx, limit * dCy, vy);
}

[[gnu::always_inline]] inline ImpactRates::SlidingSlip ImpactRates::slidingSlip(const Extended& y,
                                                                                int k) const {
  const double ux = y[kUIx + 2 * k], uy = y[kUIy + 2 * k];
  SlidingSlip slip;
  slip.speed = std::sqrt(ux * ux + uy * uy);
  if (!(slip.speed > 0)) return slip;
  const double to_direction = 1 / slip.speed;
  slip.inverse = 1 / (slip.speed + factorSlip(k));
  slip.x = ux * to_direction;
  slip.y = uy * to_direction;
  return slip;
}

// The general laws' rate with the slips' rates, where a held rate does not apply.
Extended ImpactRates::generalExtendedRate(const Extended& y) {
  return withSlipRates(generalRate(y.head<kStateSize>()));
}

// The rate sigma (1, a_x, a_y, b_x, b_y, c v_y) with the slips' rates (slipRatesOf).
[[gnu::always_inline]] inline Extended ImpactRates::scaledRate(double sigma, double ax, double ay,
                                                               double bx, double by,
                                                               double vy) const {
  Extended r;
  r[kP] = sigma;
  r[kAx] = ax * sigma;
  r[kAy] = ay * sigma;
  r[kBx] = bx * sigma;
  r[kBy] = by * sigma;
  r[kWork] = (c_ * vy) * sigma;
  r.tail<4>() = slipRatesOf(r[kP], r[kAx], r[kAy], r[kBx], r[kBy]);
  return r;
}

// rate() while the cloth is held and the nose slides (clothHeldWhileNoseSlides), at the slips
// held in y: the laws of clothHeldLaws written out, so that the stages need neither the contact
// matrix nor the general laws. The cloth sticks while its drive r0 lies inside its cone (|r0| <=
// k, compared squared) and otherwise slides along r0, or, lag-corrected, along
// lag x origin + r0, the direction of lagCorrected's blend by lagShareOf's share. The general laws
// serve an exactly zero nose slip and a drive on the cone's edge.
[[gnu::always_inline]] inline Extended ImpactRates::clothHeldRate(const Extended& y, double vy) {
  const SlidingSlip nose_slip = slidingSlip(y, 0);
  if (!(nose_slip.speed > 0)) return generalExtendedRate(y);
  const double speed_I = nose_slip.speed, inverse = nose_slip.inverse;
  const double ax = mu_[0] * nose_slip.x, ay = mu_[0] * nose_slip.y;
  const double own = 3.5 * mu_[1] * (s_ + c_ * ay) * inverse_mass_;  // k
  if (!(own > 0)) return generalExtendedRate(y);
  const double r0x = -coupling_x_ * ax * inverse_mass_;
  const double r0y = -(c_ + coupling_y_ * ay) * inverse_mass_;
  const double drive_squared = r0x * r0x + r0y * r0y;
  const double hold_limit = own * (1 - kConeSlackRelative);
  double bx, by;
  if (drive_squared <= hold_limit * hold_limit) {  // the cone holds it: the stick law
    bx = -coupling_x_ * ax * (1 / 3.5);
    by = -(c_ + coupling_y_ * ay) * (1 / 3.5);
  } else {
    const double drive = std::sqrt(drive_squared);
    if (!(drive > own)) return generalExtendedRate(y);
    double dx = r0x, dy = r0y;
    const ContactState& cloth = contacts_[1];
    if (cloth.creep_from_rest) {
      // |r0| (1 - share) / share of lagShareOf (kappa = |r0|, g = |r0| - k).
      const double growth = drive - own, half = 0.5 * growth;
      const double lag = cloth.creep_growth_order == 2 ? drive * half / (drive + half)
                                                       : growth / cloth.creep_growth_order;
      dx += lag * cloth.creep_origin.x();
      dy += lag * cloth.creep_origin.y();
    }
    const double limit = mu_[1] * (s_ + c_ * ay) / std::sqrt(dx * dx + dy * dy);
    bx = limit * dx;
    by = limit * dy;
  }
  ++evaluations_;
  return scaledRate(speed_I * inverse, ax, ay, bx, by, vy);
}

// rate() while both contacts slide (bothSliding), with the speeds cancelled out of it: with d =
// (|u_I| + s0)(|u_C| + s0), sigma = |u_I| |u_C| / d, the nose's friction rate sigma mu_w u_I /
// |u_I| = (mu_w |u_C| / d) u_I and the cloth's sigma mu_s q u_C / |u_C| with q = s + c mu_w
// u_Iy / |u_I| is (mu_s (s |u_I| + c mu_w u_Iy) / d) u_C: one division, none by a speed. A
// receding slip's s0 is taken as 0 (its factor in sigma is 1); at 5 s0 or more it keeps d from 0.
State ImpactRates::bothSlidingRate(const State& z) {
  return bothSlidingRate(withSlips(z), normalVelocity(z)).head<kStateSize>();
}

// The same at the slips held in y (see Extended) and normal velocity v_y, with the slips' own
// rates: each rate is its numerator times the one inverse, so that the slips' rates are ready as
// soon as the rest and the stages need no contact matrix between them (the stages run one after
// another, each on the one before, and the dependent operations between them set the cost).
[[gnu::always_inline]] inline Extended ImpactRates::bothSlidingRate(const Extended& y, double vy) {
  ++evaluations_;
  const double uIx = y[kUIx], uIy = y[kUIy], uCx = y[kUCx], uCy = y[kUCy];
  const double speed_I = std::sqrt(uIx * uIx + uIy * uIy);
  const double speed_C = std::sqrt(uCx * uCx + uCy * uCy);
  const double inverse = 1 / ((speed_I + factorSlip(0)) * (speed_C + factorSlip(1)));
  const double nose = mu_[0] * speed_C;
  const double cloth = mu_[1] * (s_ * speed_I + c_ * mu_[0] * uIy);
  const double sliding = speed_I * speed_C;
  const double ax = nose * uIx, ay = nose * uIy, bx = cloth * uCx, by = cloth * uCy;
  const Eigen::Vector4d slip_rates = slipRatesOf(sliding, ax, ay, bx, by);
  Extended r;
  r[kP] = sliding * inverse;
  r[kAx] = ax * inverse;
  r[kAy] = ay * inverse;
  r[kBx] = bx * inverse;
  r[kBy] = by * inverse;
  r[kWork] = (sliding * (c_ * vy)) * inverse;
  r.tail<4>() = slip_rates * inverse;
  return r;
}

// rate() when no contact is held (most of every impact), written out: the same equations as
// slips(), frictionFor() and the change of variable, without the general laws' bookkeeping.
State ImpactRates::slidingRate(const State& z) const {
  const double P = z[kP], ax = z[kAx], ay = z[kAy], bx = z[kBx], by = z[kBy];
  double sigma_numerator = 1, sigma_denominator = 1, fax = 0, fay = 0, fbx = 0, fby = 0;
  if (slipping(0)) {
    const double ux = slip0_[0].x() - (3.5 * ax + coupling_x_ * bx) * inverse_mass_;
    const double uy =
        slip0_[0].y() - (diagonal_y_ * ay + coupling_y_ * by - s_ * c_ * P) * inverse_mass_;
    const double speed = std::sqrt(ux * ux + uy * uy);
    if (contacts_[0].approaching) {
      fax = mu_[0] * contacts_[0].approach_direction.x();
      fay = mu_[0] * contacts_[0].approach_direction.y();
    } else if (speed > 0) {
      const double scale = mu_[0] / speed;
      fax = scale * ux;
      fay = scale * uy;
    } else {
      fax = mu_[0] * contacts_[0].direction.x();
      fay = mu_[0] * contacts_[0].direction.y();
    }
    if (regularized(0)) {
      sigma_numerator *= speed;
      sigma_denominator *= speed + regularizing_slip_;
    }
  }
  if (slipping(1)) {
    const double ux = slip0_[1].x() - (coupling_x_ * ax + 3.5 * bx) * inverse_mass_;
    const double uy = slip0_[1].y() - (c_ * P + coupling_y_ * ay + 3.5 * by) * inverse_mass_;
    const double speed = std::sqrt(ux * ux + uy * uy);
    const double limit = mu_[1] * (s_ + c_ * fay);
    if (contacts_[1].approaching) {
      fbx = limit * contacts_[1].approach_direction.x();
      fby = limit * contacts_[1].approach_direction.y();
    } else if (speed > 0) {
      const double scale = limit / speed;
      fbx = scale * ux;
      fby = scale * uy;
    } else {
      fbx = limit * contacts_[1].direction.x();
      fby = limit * contacts_[1].direction.y();
    }
    if (regularized(1)) {
      sigma_numerator *= speed;
      sigma_denominator *= speed + regularizing_slip_;
    }
  }
  const double vy = vy0_ - (c_ * P - s_ * ay + by) * inverse_mass_;
  return scaledRate(sigma_numerator / sigma_denominator, fax, fay, fbx, fby, vy).head<kStateSize>();
}

// Whether a slipping contact's slip turned by more than a right angle from `before` to `after`
// (the slips at a step's start and end).
bool ImpactRates::slipReversed(const std::array<Eigen::Vector2d, 2>& before,
                               const std::array<Eigen::Vector2d, 2>& after) const {
  for (int k = 0; k < 2; ++k) {
    if (slipping(k) && !(before[k].dot(after[k]) > 0)) return true;
  }
  return false;
}

// The stages' rates of those three cases, inlined into them (as lambdas GCC stopped inlining them
// once there were two).
struct ImpactRates::BothSlidingStage {
  ImpactRates* solver;
  [[gnu::always_inline]] Extended operator()(const Extended& y) const {
    return solver->bothSlidingRate(y, solver->normalVelocity(y));
  }
};
struct ImpactRates::ClothHeldStage {
  ImpactRates* solver;
  [[gnu::always_inline]] Extended operator()(const Extended& y) const {
    return solver->clothHeldRate(y, solver->normalVelocity(y));
  }
};
struct ImpactRates::NoseHeldStage {
  ImpactRates* solver;
  [[gnu::always_inline]] Extended operator()(const Extended& y) const {
    return solver->noseHeldRate(y, solver->normalVelocity(y));
  }
};

template <typename Rate>
Step ImpactRates::extendedStep(const State& z, const State& k1, double h, const Rate& rate) {
  return finishStep(z, dop853::stages(withSlips(z), withSlipRates(k1), h, rate), h);
}

// One Dormand-Prince step. While both contacts slide, or one is held while the other slides, its
// stages carry the slips (Extended) into that case's own rate, which GCC inlines into them.
Step ImpactRates::rungeKuttaStep(const State& z, const State& k1, double h) {
  if (bothSliding()) return extendedStep(z, k1, h, BothSlidingStage{this});
  if (clothHeldWhileNoseSlides()) return extendedStep(z, k1, h, ClothHeldStage{this});
  if (noseHeldWhileClothSlides()) return extendedStep(z, k1, h, NoseHeldStage{this});
  return finishStep(z, dop853::stages(z, k1, h, [this](const State& y) { return rate(y); }), h);
}

// The step from z given its stages: its end, the rate there and its error.
// (Of either vector type: only the state's part of each stage is read, none copied.)
template <typename Vector>
Step ImpactRates::finishStep(const State& z, const dop853::Stages<Vector>& stages, double h) {
  Step step;
  step.z = stages.end.template head<kStateSize>();
  step.rate_at_end = stages.rate_at_end.template head<kStateSize>();
  State third, fifth;
  dop853::errorDifferences(stages, &third, &fifth);
  return finishStep(z, step, third, fifth, h);
}

// The step's error from the third- and fifth-order estimates' differences.
Step ImpactRates::finishStep(const State& z, Step step, State third, State fifth, double h) {
  using dop853::kThirdOrderWeight;
  // Combined estimate: |h| e5^2 / sqrt(n (e5^2 + w e3^2)), the norms scaled by the tolerances.
  // Only the error across the path counts: an error along it (of P and of the rest in the
  // proportions dz/dP at the step's end) is an error of the parameter tau, which the change of
  // variable makes large where sigma varies fast (a small slip) but which moves the step's end
  // along the path, not off it. So the estimates are taken at equal P. Not where a slip turned
  // by more than a right angle within the step (it passed by zero): there the end's direction
  // does not stand for the step, and the whole estimate counts.
  // (Two divisions and products with the scales' reciprocals: this runs between a step's last
  // rate and the next step's first stage, where each division's latency, and eighteen divisions'
  // turns at the divider, were waited for.)
  const std::array<Eigen::Vector2d, 2> slips_before = slips(z), slips_after = slips(step.z);
  step.slips_at_end = slips_after;
  if (!slipReversed(slips_before, slips_after) && step.rate_at_end[kP] > 0) {
    const double third_along = third[kP] / step.rate_at_end[kP];
    const double fifth_along = fifth[kP] / step.rate_at_end[kP];
    third -= third_along * step.rate_at_end;
    fifth -= fifth_along * step.rate_at_end;
    third[kP] = fifth[kP] = 0;
  }
  third = third.cwiseProduct(inverse_error_scale_);
  fifth = fifth.cwiseProduct(inverse_error_scale_);
  const double fifth_squared = fifth.squaredNorm(), third_squared = third.squaredNorm();
  double denominator = fifth_squared + kThirdOrderWeight * third_squared;
  if (!(denominator > 0)) denominator = 1;
  // Error per unit step: a step may add error in proportion to the share of the impact's impulse
  // it covers, so the errors of many steps add up to about the tolerance, not to their number
  // times it; no less than min_error_share of it (ExactSolverOptions).
  const double share = std::max(std::abs(step.z[kP] - z[kP]) / impulse_scale_, min_error_share_);
  const double error_per_share =
      std::abs(h) * fifth_squared / (std::sqrt(State::RowsAtCompileTime * denominator) * share);
  step.error = std::max(error_per_share, smallSlipGrowthError(slips_before, slips_after));
  return step;
}

// The step's change of a small growing slip against kSmallSlipGrowthPerStep, as an error of the
// step's order (so that the step factor shortens the next try toward the allowed change, by at
// most its clamp per try), from the slips at the step's start and end; 0 when no such slip
// changes beyond it.
double ImpactRates::smallSlipGrowthError(const std::array<Eigen::Vector2d, 2>& before,
                                         const std::array<Eigen::Vector2d, 2>& after) const {
  double error = 0;
  for (int k = 0; k < 2; ++k) {
    if (!slipping(k) || contacts_[k].approaching) continue;
    const double size = before[k].norm();
    if (!(size < regularizing_slip_) || !(after[k].norm() > size)) continue;
    const double ratio = (after[k] - before[k]).norm() / (kSmallSlipGrowthPerStep * size);
    if (ratio > 1) error = std::max(error, std::pow(ratio, dop853::kErrorOrder));
  }
  return error;
}

}  // namespace baize::physics::cushion_exact
