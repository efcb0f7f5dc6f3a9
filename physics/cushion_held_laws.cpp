#include "physics/cushion_held_laws.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "physics/polynomial_roots.h"

namespace baize::physics::cushion_exact {

// A slipping contact is taken as sliding steadily along phi* only while its misalignment is below
// this fraction of the limit: well below where a held law ends, so that a contact just released
// is not held again at once.
constexpr double kSteadyCreepHold = 0.25;
// The turn (rad) over which lagShare differentiates the slip rate's turn about phi*: small against
// the curvature of r(d) over the circle, large against rounding of the rates (1e-16 relative).
constexpr double kLagProbeAngle_rad = 1e-5;
// Newton's method for phi*: the angle step of its numerical derivative (rad), the largest turn per
// iteration (rad), the convergence test (rad) and the iteration limit.
constexpr double kCreepAngleStep = 1e-6;
constexpr double kCreepMaxTurn = 0.5;
constexpr double kCreepAngleTolerance = 1e-10;
constexpr int kMaxCreepIterations = 30;
// A floor under |du/dP| (times M) that keeps phi*'s equation defined where the rate vanishes.
constexpr double kRateFloor = 1e-9;
// The slip rate counts as affine in the friction direction when r(-x) misses r0 - W x by at most
// this fraction of the rates' size (rounding), and vanishes along a direction (the cone's edge)
// when it is that small there; a closed-form root of phi*'s equation is kept when its residual is
// within the second fraction (rounding of the quartic's roots).
constexpr double kAffineCheckRelative = 1e-12;
constexpr double kAffineRootRelative = 1e-9;
// Samples on the circle when searching for the direction a contact slips off in from rest.
constexpr int kDirectionSamples = 72;

// phi* of the cloth contact while the cushion contact slides (or is frictionless), in closed
// form: the cushion's friction a then does not depend on the cloth's direction d, and the cloth's
// own friction mu_s q d (q = s + c a_y) enters its slip rate isotropically, du_C/dP = r0 - k d
// with k = 7/2 mu_s q / M. So phi* = r0 / |r0|, along which the slip grows at |r0| - k (the cone
// cannot hold the contact exactly when |r0| > k). This is the held contact of every rolling or
// nearly rolling ball, the common case. Returns false when it does not apply.
bool HeldLaws::clothCreepDirection(int k, const Laws& laws, Eigen::Vector2d* result) const {
  if (k != 1 || laws.stick[0]) return false;
  const ClothDrive drive = clothDrive(laws);
  const double size = drive.rate.norm();
  if (!(size > drive.own)) return false;
  *result = drive.rate / size;
  return true;
}

HeldLaws::ClothDrive HeldLaws::clothDrive(const Laws& laws) const {
  const Eigen::Vector2d a = contacts_[0].frictionless ? Eigen::Vector2d::Zero()
                                                      : Eigen::Vector2d(mu_[0] * laws.direction[0]);
  return {Eigen::Vector2d(-coupling_x_ * a.x() * inverse_mass_,
                          -(c_ + coupling_y_ * a.y()) * inverse_mass_),
          3.5 * mu_[1] * (s_ + c_ * a.y()) * inverse_mass_};
}

// The direction phi* a held contact k slides along when its cone cannot hold it: the slip it then
// makes grows along phi* (cross(phi*, du_k/dP) = 0 with du_k/dP . phi* > 0). Newton on the angle
// from `guess`; returns false if that does not converge to such a direction.
bool HeldLaws::creepDirection(int k, Laws laws, const Eigen::Vector2d& guess,
                              Eigen::Vector2d* result) const {
  if (clothCreepDirection(k, laws, result)) return true;
  const AffineNewton affine = creepDirectionAffineNewton(k, laws, guess, result);
  if (affine != AffineNewton::NotAffine) return affine == AffineNewton::Found;
  laws.stick[k] = false;
  auto turn = [&](double phi, double* growth) {
    laws.direction[k] = Eigen::Vector2d(std::cos(phi), std::sin(phi));
    const Eigen::Vector2d r = slipRate(k, frictionFor(laws));
    *growth = r.dot(laws.direction[k]);
    return cross(laws.direction[k], r) / (r.norm() + kRateFloor * inverse_mass_);
  };
  // Secant iterations, started with a difference over a small angle: one evaluation of the
  // rate per iteration (a central difference takes three), converging almost as fast from the
  // close guesses it is given (the last phi*).
  double phi = std::atan2(guess.y(), guess.x()), growth = 0;
  double value = turn(phi, &growth);
  double previous_phi = phi + kCreepAngleStep, previous_growth = 0;
  double previous_value = turn(previous_phi, &previous_growth);
  for (int it = 0; it < kMaxCreepIterations; ++it) {
    const double slope = (value - previous_value) / (phi - previous_phi);
    if (!(slope != 0)) break;
    const double change = std::clamp(-value / slope, -kCreepMaxTurn, kCreepMaxTurn);
    previous_phi = phi;
    previous_value = value;
    phi += change;
    value = turn(phi, &growth);
    if (std::abs(change) <= kCreepAngleTolerance) {
      if (!(growth > 0)) return false;
      *result = Eigen::Vector2d(std::cos(phi), std::sin(phi));
      return true;
    }
  }
  return false;
}

// Contact k's slip rate as r(d) = r0 + W d in its sliding direction d, from the rates at d = 0,
// x and y; false when it is not affine (the rate at -x misses r0 - W x by more than rounding).
bool HeldLaws::affineSlipRate(int k, Laws laws, Eigen::Vector2d* r0, Eigen::Matrix2d* W) const {
  laws.stick[k] = false;
  auto rateAlong = [&](const Eigen::Vector2d& d) {
    laws.direction[k] = d;
    return slipRate(k, frictionFor(laws));
  };
  *r0 = rateAlong(Eigen::Vector2d::Zero());
  W->col(0) = rateAlong(Eigen::Vector2d::UnitX()) - *r0;
  W->col(1) = rateAlong(Eigen::Vector2d::UnitY()) - *r0;
  const Eigen::Vector2d check = rateAlong(-Eigen::Vector2d::UnitX());
  return (check - (*r0 - W->col(0))).norm() <=
         kAffineCheckRelative * (r0->norm() + W->col(0).norm());
}

HeldLaws::AffineNewton HeldLaws::creepDirectionAffineNewton(int k, Laws laws,
                                                            const Eigen::Vector2d& guess,
                                                            Eigen::Vector2d* result) const {
  if (k != 0) return AffineNewton::NotAffine;  // the cloth's is rational while the nose sticks
  Eigen::Vector2d r0;
  Eigen::Matrix2d W;
  if (!affineSlipRate(k, laws, &r0, &W)) return AffineNewton::NotAffine;
  return affineNewton(r0, W, guess, result) ? AffineNewton::Found : AffineNewton::NotFound;
}

// The Newton iterations of creepDirectionAffineNewton on r(d) = r0 + W d from `guess`.
bool HeldLaws::affineNewton(const Eigen::Vector2d& r0, const Eigen::Matrix2d& W,
                            const Eigen::Vector2d& guess, Eigen::Vector2d* result) {
  Eigen::Vector2d d = guess.normalized();
  for (int it = 0; it < kMaxCreepIterations; ++it) {
    const Eigen::Vector2d r = r0 + W * d, across(-d.y(), d.x());
    const double slope = cross(across, r) + cross(d, W * across);
    if (!(slope != 0)) break;
    const double change = std::clamp(-cross(d, r) / slope, -kCreepMaxTurn, kCreepMaxTurn);
    d = (d + change * across).normalized();
    if (std::abs(change) <= kCreepAngleTolerance) {
      // On the cone's edge the slip rate vanishes along phi* (the friction there is what
      // sticking needs): its growth is zero up to rounding, of either sign, and the root is the
      // answer (lawsAt slides the held contact along it; slidesSteadily takes a slip lying along
      // it as sliding steadily on the edge). Refused, it sent lawsAt on to a search of the whole
      // circle, dozens of times the cost (a third of the time of an impact that grazes the edge
      // for long).
      const Eigen::Vector2d rate = r0 + W * d;
      const double scale = r0.norm() + W.col(0).norm() + W.col(1).norm();
      const bool on_edge = rate.norm() <= kAffineCheckRelative * scale;
      if (!(rate.dot(d) > 0) && !on_edge) break;
      *result = d;
      return true;
    }
  }
  return false;
}

// phi* in closed form when the slip rate is affine in the friction direction d, r(d) = r0 + W d
// (the other contact slides or is frictionless; with it stuck its stick law makes r rational):
// cross(d, r0 + W d) = 0 is then A cos + B sin + C cos 2phi + D sin 2phi + E = 0, a quartic in
// t = tan(phi / 2). Returns false when r is not affine or no root has the slip growing.
bool HeldLaws::creepDirectionAffine(int k, Laws laws, Eigen::Vector2d* result) const {
  Eigen::Vector2d r0;
  Eigen::Matrix2d W;
  return affineSlipRate(k, laws, &r0, &W) && affineCreepDirection(r0, W, result);
}

// creepDirectionAffine's roots for the slip rate r(d) = r0 + W d.
bool HeldLaws::affineCreepDirection(const Eigen::Vector2d& r0, const Eigen::Matrix2d& W,
                                    Eigen::Vector2d* result) {
  const Eigen::Vector2d wx = W.col(0), wy = W.col(1);
  const double W00 = wx.x(), W10 = wx.y(), W01 = wy.x(), W11 = wy.y();
  const physics::PolynomialCoefficients quartic = {r0.y() + W10, -2 * r0.x() + 2 * (W11 - W00),
                                                   -2 * W10 - 4 * W01,
                                                   -2 * r0.x() - 2 * (W11 - W00), -r0.y() + W10};
  std::vector<double> angles;
  for (double t : physics::realRoots(quartic)) angles.push_back(2 * std::atan(t));
  angles.push_back(M_PI);  // t = infinity: a root when the quartic's leading term vanishes
  double best_growth = 0;
  for (double phi : angles) {
    const Eigen::Vector2d d(std::cos(phi), std::sin(phi));
    const Eigen::Vector2d r = r0 + wx * d.x() + wy * d.y();
    if (std::abs(cross(d, r)) > kAffineRootRelative * (r0.norm() + wx.norm() + wy.norm())) continue;
    if (r.dot(d) > best_growth) {
      best_growth = r.dot(d);
      *result = d;
    }
  }
  return best_growth > 0;
}

// The same by a search over the whole circle (robust, for a first guess): of the directions along
// which the slip grows along itself, the one where it grows fastest.
Eigen::Vector2d HeldLaws::creepDirectionSearch(int k, Laws laws) const {
  laws.stick[k] = false;
  // The cloth contact while the nose slides: r0 / |r0| (clothCreepDirection), also where its cone
  // holds it (then no direction grows, and the search below ends on the same r0 / |r0|).
  if (k == 1 && !laws.stick[0]) {
    const Eigen::Vector2d r0 = clothDrive(laws).rate;
    if (r0.norm() > 0) return r0.normalized();
  }
  Eigen::Vector2d solved = Eigen::Vector2d::Zero();  // set whenever a closed form applies
  Eigen::Vector2d r0;
  Eigen::Matrix2d W;
  const bool affine = affineSlipRate(k, laws, &r0, &W);
  if (affine && affineCreepDirection(r0, W, &solved)) return solved;
  // Affine, the growth d . r(d) changes by at most |r0| + 2 |W| per radian of d's turn (its
  // derivative is d' . r0 + d' . (W + W^T) d): a bracket whose ends' growths lie that far below
  // zero (plus rounding) holds no root the search would keep, and is not bisected. (A held nose
  // whose cone holds it comes here once per stick; its bisections were half the search's cost.)
  const double growth_slope = affine ? r0.norm() + 2 * W.norm() : 0;
  const double growth_rounding =
      kAffineCheckRelative * (r0.norm() + W.col(0).norm() + W.col(1).norm());
  auto rateAlong = [&](double phi) {
    laws.direction[k] = Eigen::Vector2d(std::cos(phi), std::sin(phi));
    return slipRate(k, frictionFor(laws));
  };
  auto turn = [&](double phi) {
    return cross(Eigen::Vector2d(std::cos(phi), std::sin(phi)), rateAlong(phi));
  };
  const double spacing = 2 * M_PI / kDirectionSamples;
  // The samples' directions, the same for every search (taken once: a sine and cosine each).
  static const std::array<Eigen::Vector2d, kDirectionSamples + 1> sample_directions = [spacing] {
    std::array<Eigen::Vector2d, kDirectionSamples + 1> directions;
    for (int i = 0; i <= kDirectionSamples; ++i)
      directions[i] = Eigen::Vector2d(std::cos(i * spacing), std::sin(i * spacing));
    return directions;
  }();
  std::array<double, kDirectionSamples + 1> turns, growths;
  for (int i = 0; i <= kDirectionSamples; ++i) {
    laws.direction[k] = sample_directions[i];
    const Eigen::Vector2d r = slipRate(k, frictionFor(laws));
    turns[i] = cross(laws.direction[k], r);
    growths[i] = laws.direction[k].dot(r);
  }
  double best_growth = 0, best_phi = 0;
  for (int i = 0; i < kDirectionSamples; ++i) {
    if ((turns[i] <= 0) == (turns[i + 1] <= 0)) continue;
    if (affine && 0.5 * (growths[i] + growths[i + 1] + growth_slope * spacing) < -growth_rounding) {
      continue;
    }
    double lo = i * spacing, hi = (i + 1) * spacing;
    const bool lo_negative = turns[i] <= 0;
    for (int it = 0; it < 60 && hi - lo > 4 * kEpsilon; ++it) {
      const double mid = 0.5 * (lo + hi);
      ((turn(mid) <= 0) == lo_negative ? lo : hi) = mid;
    }
    const double phi = 0.5 * (lo + hi);
    const double growth = rateAlong(phi).dot(Eigen::Vector2d(std::cos(phi), std::sin(phi)));
    if (growth > best_growth) {
      best_growth = growth;
      best_phi = phi;
    }
  }
  if (best_growth > 0) return Eigen::Vector2d(std::cos(best_phi), std::sin(best_phi));
  // None (not expected: the contact matrix is positive definite): along the rate it would get.
  const Eigen::Vector2d r = rateAlong(0) + rateAlong(M_PI);
  return r.norm() > 0 ? Eigen::Vector2d(r.normalized()) : Eigen::Vector2d::UnitX();
}

// lawsAt's most common case written out (a rolling ball's cloth contact, held while the cushion
// contact slides or is frictionless): the stick friction the cloth would need is M r0 / (7/2) and
// its cone is mu_s q, so it sticks while |r0| <= k and otherwise slides along phi* = r0 / |r0|
// (see clothCreepDirection). False (laws untouched) within rounding of the cone's edge, which
// the general path settles.
bool HeldLaws::clothHeldLaws(Laws* laws) const {
  const ClothDrive drive = clothDrive(*laws);
  const Eigen::Vector2d& r0 = drive.rate;
  const double own = drive.own;
  const double size = r0.norm();
  if (1 - size / own >= kConeSlackRelative) return true;  // the cone holds it: it sticks
  if (!(size > own)) return false;
  laws->stick[1] = false;
  laws->direction[1] = r0 / size;
  if (contacts_[1].creep_from_rest) {
    laws->direction[1] =
        lagCorrected(contacts_[1].creep_origin, laws->direction[1],
                     lagShareOf(size - own, size, contacts_[1].creep_growth_order));
  }
  return true;
}

// The share of phi*'s turn since its slip was zero that held contact k's slip follows (see
// lagCorrected), for any slip rate r(d): near phi* the slip's direction theta turns at
// d theta/dP = -kappa (theta - phi*) / |u| with kappa = -d cross(d, r(d)) / d theta at phi*, and
// with |u| = g (P - P0) and phi* turning steadily the slip follows the share kappa / (g + kappa),
// g = r(phi*) . phi* its growth. A slip that starts where the cone stops holding it grows from a
// zero rate, |u| ~ (P - P0)^2, and lags about half as much (creep_growth_order; lagShareOf). (For
// the cloth, kappa = |r0| and g = |r0| - k: clothHeldLaws.) 1 (no correction) where no slip grows
// along phi*.
double HeldLaws::lagShare(int k, Laws laws, const Eigen::Vector2d& phi) const {
  laws.stick[k] = false;
  laws.direction[k] = phi;
  const double growth = slipRate(k, frictionFor(laws)).dot(phi);
  const Eigen::Vector2d turned = probeTurned(phi);
  laws.direction[k] = turned;
  const double restoring = -cross(turned, slipRate(k, frictionFor(laws))) / kLagProbeAngle_rad;
  return lagShareOf(growth, restoring, contacts_[k].creep_growth_order);
}

// phi turned by kLagProbeAngle_rad.
Eigen::Vector2d HeldLaws::probeTurned(const Eigen::Vector2d& phi) {
  const double cos_probe = std::cos(kLagProbeAngle_rad), sin_probe = std::sin(kLagProbeAngle_rad);
  return {phi.x() * cos_probe - phi.y() * sin_probe, phi.x() * sin_probe + phi.y() * cos_probe};
}

// The share from the slip's growth g along phi* and the restoring rate kappa of its direction.
// Growing linearly (|u| = g (P - P0)) the slip lags phi* turning steadily by |u| phi*' / (g +
// kappa), exactly: the share kappa / (g + kappa). Growing from a zero rate (|u| = a (P - P0)^2, g
// = 2 a (P - P0) now) the lag solves |u| (phi*' - lag') = kappa lag, whose series is |u| phi*' /
// kappa (1 - g / kappa + ...); the share (kappa + g / 2) / (kappa + g) matches it to second order
// (kappa / (g / 2 + kappa), first order only, ended the held law of a break's nose released from
// its cone's edge at a slip 0.7 times as large, and cost that impact 8 % more evaluations).
double HeldLaws::lagShareOf(double growth, double restoring, double growth_order) {
  if (!(growth > 0) || !(restoring > 0)) return 1;
  if (growth_order == 2) return (restoring + 0.5 * growth) / (restoring + growth);
  return restoring / (growth / growth_order + restoring);
}

// lagShare for the nose, whose slip rate is affine in its friction direction, r(d) = r0 + W d.
double HeldLaws::affineLagShare(const Eigen::Vector2d& r0, const Eigen::Matrix2d& W,
                                const Eigen::Vector2d& phi, double growth_order) {
  const double growth = (r0 + W * phi).dot(phi);
  const Eigen::Vector2d turned = probeTurned(phi);
  const double restoring = -cross(turned, r0 + W * turned) / kLagProbeAngle_rad;
  return lagShareOf(growth, restoring, growth_order);
}

// The laws in force at slips u: slipping contacts slide along their slips; held contacts stick if
// their cones can hold them and otherwise slide along phi* (found from their `creep` guesses).
// When both are held and the friction that sticks both lies outside both cones, one slides first
// (slidesFirst) and the other's cone is judged again against that: it may hold it then (a rolling
// ball's cloth caught sliding steadily on its cone's edge while the nose sticks). Letting both
// slide at once there let a stuck nose slip, its slip grown from zero to 3e-4 V in one step
// without an event, 1.6e-7 V0 off the converged solution (a grippy impact).
Laws HeldLaws::lawsAt(const std::array<Eigen::Vector2d, 2>& u, std::array<double, 2>* speed) const {
  Laws laws;
  for (int k = 0; k < 2; ++k) {
    const double size = u[k].norm();
    if (speed) (*speed)[k] = size;
    laws.stick[k] = held(k);
    laws.direction[k] = contacts_[k].approaching ? contacts_[k].approach_direction
                        : size > 0               ? Eigen::Vector2d(u[k] / size)
                                                 : contacts_[k].direction;
  }
  if (!held(0) && !held(1)) return laws;
  if (held(1) && !held(0) && clothHeldLaws(&laws)) return laws;
  for (int round = 0; round < 2; ++round) {
    const int k = slidesFirst(laws, frictionFor(laws), u);
    if (k < 0) break;
    slideAlongCreep(k, &laws);
  }
  return laws;
}

// Of the held contacts that stick under `laws`, the one whose cone cannot hold friction f and
// that slides first; -1 if every such cone holds. With both outside: the one that still slips
// (caught sliding steadily, its slip above the vanishing threshold) while the other's slip is
// zero, so that a moving contact goes on moving and a stuck one stays stuck as far as the cones
// allow; otherwise the one whose cone is exceeded more (NaN counts as outside, ties the nose).
int HeldLaws::slidesFirst(const Laws& laws, const Friction& f,
                          const std::array<Eigen::Vector2d, 2>& u) const {
  std::array<bool, 2> outside = {false, false};
  std::array<double, 2> margin = {0, 0};
  for (int k = 0; k < 2; ++k) {
    if (!laws.stick[k] || !held(k)) continue;
    margin[k] = coneMargin(k, f);
    outside[k] = !(margin[k] >= kConeSlackRelative);
  }
  if (!outside[0] || !outside[1]) return outside[0] ? 0 : outside[1] ? 1 : -1;
  const bool moving_I = u[0].norm() > vanished_slip_, moving_C = u[1].norm() > vanished_slip_;
  if (moving_I != moving_C) return moving_I ? 0 : 1;
  return std::isnan(margin[1]) || margin[1] < margin[0] ? 1 : 0;
}

// Held contact k's law set to sliding along its phi* under the other contact's law in `laws`.
void HeldLaws::slideAlongCreep(int k, Laws* laws) const {
  Eigen::Vector2d phi;
  if (!creepDirection(k, *laws, contacts_[k].creep, &phi)) phi = creepDirectionSearch(k, *laws);
  if (lagCorrected(k)) phi = lagCorrected(contacts_[k].creep_origin, phi, lagShare(k, *laws, phi));
  laws->stick[k] = false;
  laws->direction[k] = phi;
}

// How far inside its cone held contact k's stick friction would be at z (negative: outside),
// the other contact following its own law given that k sticks: if it is held too, it slides along
// its phi* when lawsAt would let it slide first (slidesFirst), and k's margin is taken against
// that. So the sign says whether lawsAt holds k or lets it slide.
double HeldLaws::neededMargin(int k, const State& z) const {
  const std::array<Eigen::Vector2d, 2> u = slips(z);
  Laws laws;
  for (int j = 0; j < 2; ++j) {
    laws.stick[j] = held(j);
    laws.direction[j] =
        u[j].norm() > 0 ? Eigen::Vector2d(u[j].normalized()) : contacts_[j].direction;
  }
  const int other = 1 - k;
  if (held(other) && slidesFirst(laws, frictionFor(laws), u) == other)
    slideAlongCreep(other, &laws);
  return coneMargin(k, frictionFor(laws));
}

// How much more error the held law of contact k may make at z before its contact has to slip as
// its own slip says (m/s; negative: past it): the limit less its slip's misalignment with phi*,
// or less its slip scaled so that the limit is reached at the regularizing slip. Positive, and
// at the limit, while its cone holds it (then the cone events apply).
double HeldLaws::creepRoom(int k, const State& z) const {
  const std::array<Eigen::Vector2d, 2> u = slips(z);
  const Laws laws = lawsAt(u, nullptr);
  if (laws.stick[k]) return creep_error_limit_;
  const double misalignment = std::abs(cross(u[k], laws.direction[k]));
  // (A slip from rest under the lag-corrected law is measured by its misalignment alone.)
  const double size = lagCorrected(k) ? 0 : u[k].norm() * (creep_error_limit_ / regularizing_slip_);
  return creep_error_limit_ - std::max(misalignment, size);
}

// Whether slipping contact k slides steadily on the edge of its cone: its cone cannot hold it and
// its small slip already lies along phi* (to within what the held law may miss). Such a slip
// changes slowly while its direction is held stiffly in place; the held law describes it exactly
// and is integrated in P.
bool HeldLaws::slidesSteadily(int k, const std::array<Eigen::Vector2d, 2>& u) {
  Laws laws = lawsAt(u, nullptr);
  laws.stick[k] = true;
  if (coneMargin(k, frictionFor(laws)) >= kConeSlackRelative) return false;
  Eigen::Vector2d phi;
  if (!creepDirection(k, laws, u[k].normalized(), &phi)) return false;
  // Along phi*, not against it: a slip passing through zero lies on phi*'s line too, but
  // sliding along phi* would reverse its friction before its slip has reached zero.
  if (!(u[k].dot(phi) > 0) || std::abs(cross(u[k], phi)) >= kSteadyCreepHold * creep_error_limit_)
    return false;
  contacts_[k].creep = phi;
  return true;
}

}  // namespace baize::physics::cushion_exact
