// A reference for the exact cushion solver's contact log (which contact sticks, from which impulse
// P), built from the equations of the Mathavan 2010 model alone: explicit Euler in P with many
// fixed increments, each contact's friction frozen along its slip over an increment (the paper's
// scheme, section 3.4). It shares nothing with the exact solver but the model: no change of
// variable, no held laws, no events. Where a slip reaches zero and the cone can hold it, the frozen
// direction flips from one increment to the next and the slip chatters within about one
// increment's change of zero; as the increment shrinks this converges to sticking (Filippov's
// solution), so a stick shows as a run of increments whose slip stays within that chatter band.
// Its onset is located where the slip first comes within one increment's change of zero, at the
// point of that increment nearest zero.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "physics/cushion_model.h"

namespace baize::physics::test {

// A slip within this many times the largest change an increment makes to it (over the whole
// impact) is taken as chattering about zero: a 1D chatter stays within one change (it turns back
// once past zero), and a 2D one within a few.
constexpr double kChatterSpan = 3;

// One stick of the reference: contact (0 the cushion nose, 1 the cloth) stuck over [from, to].
struct ReferenceStick {
  int contact = 0;
  double from_Ns = 0;
  double to_Ns = 0;
};

struct ReferenceContactLog {
  std::vector<ReferenceStick> sticks;  // in order of onset for each contact
  double increment_Ns = 0;             // dP
  double final_impulse_Ns = 0;         // P_f
  BallVelocity after;
};

// The slips at I (basis x, Y') and C (basis x, y) written out from v + w x r at each contact.
inline std::array<Eigen::Vector2d, 2> referenceSlips(double R, double s, double c,
                                                     const BallVelocity& ball) {
  const Eigen::Vector3d& v = ball.v;
  const Eigen::Vector3d& w = ball.w;
  return {Eigen::Vector2d(v.x() + R * (w.y() * s - w.z() * c), -v.y() * s + R * w.x()),
          Eigen::Vector2d(v.x() - R * w.y(), v.y() + R * w.x())};
}

// One Euler increment dP with friction against the slips u (none where a slip is exactly zero):
// eq. 14a and the five rates the paper leaves out, written from the impulses on the ball (the
// normal impulse and friction mu_w at I, friction mu_s q at C, the table's q keeping v_z at 0).
inline void referenceIncrement(const CushionParams& p, double s, double c,
                               const std::array<Eigen::Vector2d, 2>& u, double dP,
                               BallVelocity* ball) {
  const double M = p.mass_kg, k = 5 / (2 * p.mass_kg * p.radius_m);
  const double mu_w = p.cushion_friction, mu_s = p.cloth_friction;
  const Eigen::Vector2d d_I =
      u[0].norm() > 0 ? Eigen::Vector2d(u[0].normalized()) : Eigen::Vector2d::Zero();
  const Eigen::Vector2d d_C =
      u[1].norm() > 0 ? Eigen::Vector2d(u[1].normalized()) : Eigen::Vector2d::Zero();
  const double q = s + mu_w * d_I.y() * c;  // table normal impulse per unit P (eq. 8)
  const Eigen::Vector3d dv(-(mu_w * d_I.x() + mu_s * q * d_C.x()) / M,
                           -(c - mu_w * s * d_I.y() + mu_s * q * d_C.y()) / M, 0);
  const Eigen::Vector3d dw(-k * (mu_w * d_I.y() + mu_s * q * d_C.y()),
                           -k * (mu_w * d_I.x() * s - mu_s * q * d_C.x()), k * mu_w * d_I.x() * c);
  ball->v += dv * dP;
  ball->w += dw * dP;
}

// The stick runs of contact k over the recorded slips: maximal runs of increments within the
// chatter band that reach zero, each from where its slip first comes within one increment's change
// of zero (a 1D slip crossing zero, or a 2D one whose Euler increment overshoots it: there the
// scheme no longer resolves the slip, which then chatters) to its last increment. The onset is the
// point of that increment nearest zero. A run that never comes that close is a slip passing by
// zero: not a stick.
inline void referenceStickRuns(int k, const std::vector<double>& P,
                               const std::vector<Eigen::Vector2d>& u,
                               std::vector<ReferenceStick>* sticks) {
  double largest_change = 0;
  for (std::size_t n = 0; n + 1 < u.size(); ++n)
    largest_change = std::max(largest_change, (u[n + 1] - u[n]).norm());
  const double band = kChatterSpan * largest_change;
  std::size_t n = 0;
  while (n < u.size()) {
    if (u[n].norm() > band) {
      ++n;
      continue;
    }
    std::size_t end = n;
    while (end + 1 < u.size() && u[end + 1].norm() <= band) ++end;
    double onset = -1;
    for (std::size_t m = n == 0 ? 0 : n - 1; onset < 0 && m < end; ++m) {
      const Eigen::Vector2d step = u[m + 1] - u[m];
      if (step.norm() < u[m].norm()) continue;
      const double t =
          step.squaredNorm() > 0 ? std::clamp(-u[m].dot(step) / step.squaredNorm(), 0.0, 1.0) : 0.0;
      onset = P[m] + t * (P[m + 1] - P[m]);
    }
    if (onset >= 0) sticks->push_back({k, onset, P[end]});
    n = end + 1;
  }
}

// The reference for an impact with `increments` increments over the frictionless impulse
// (1 + e) M v_y0 / cos theta (the impact takes about that many).
inline ReferenceContactLog referenceContactLog(const CushionParams& p, const BallVelocity& incoming,
                                               int increments) {
  const double s = contactSinTheta(p), c = std::sqrt(1 - s * s);
  ReferenceContactLog log;
  const double dP = (1 + p.restitution) * p.mass_kg * incoming.v.y() / (c * increments);
  log.increment_Ns = dP;
  BallVelocity ball = incoming;
  double P = 0, work = 0, target = 0;
  bool compressing = true;
  std::vector<double> impulses;
  std::array<std::vector<Eigen::Vector2d>, 2> slips;
  impulses.reserve(2 * increments);  // (an impact takes about `increments`)
  for (auto& list : slips) list.reserve(2 * increments);
  for (int n = 0;; ++n) {
    if (n > 20 * increments) throw std::logic_error("reference contact log: the impact never ends");
    const std::array<Eigen::Vector2d, 2> u = referenceSlips(p.radius_m, s, c, ball);
    impulses.push_back(P);
    for (int k = 0; k < 2; ++k) slips[k].push_back(u[k]);
    const BallVelocity before = ball;
    referenceIncrement(p, s, c, u, dP, &ball);
    const double dW = 0.5 * c * (before.v.y() + ball.v.y()) * dP;  // trapezoidal (eq. 17a)
    if (compressing && ball.v.y() <= 0) {  // compression ends inside: W_c at v_y = 0
      const double t = before.v.y() / (before.v.y() - ball.v.y());
      target = (1 - p.restitution * p.restitution) * (work + 0.5 * c * before.v.y() * t * dP);
      compressing = false;
    }
    const double next_work = work + dW;
    if (!compressing && next_work <= target) {  // restitution ends inside: interpolated
      const double t = (work - target) / (work - next_work);
      log.after.v = before.v + t * (ball.v - before.v);
      log.after.w = before.w + t * (ball.w - before.w);
      log.final_impulse_Ns = P + t * dP;
      break;
    }
    work = next_work;
    P += dP;
  }
  for (int k = 0; k < 2; ++k) {
    if ((k == 0 ? p.cushion_friction : p.cloth_friction) > 0)
      referenceStickRuns(k, impulses, slips[k], &log.sticks);
  }
  return log;
}

// The sticks of the reference at `increments` longer than `shortest_Ns`, their onsets extrapolated
// from the reference at half as many increments (Richardson: the Euler trajectory's error, and so
// an onset's, is first order in dP), with the change between the two as their error estimate. A
// stick with no partner at half the increments (onset within shortest_Ns) keeps its onset and gets
// an infinite estimate.
struct ExtrapolatedStick {
  ReferenceStick stick;
  double onset_error_Ns = 0;
};
struct ExtrapolatedContactLog {
  std::vector<ExtrapolatedStick> sticks;
  BallVelocity after;  // of the reference at `increments`
};
inline ExtrapolatedContactLog extrapolatedContactLog(const CushionParams& p,
                                                     const BallVelocity& incoming, int increments,
                                                     double shortest_Ns) {
  const ReferenceContactLog fine = referenceContactLog(p, incoming, increments);
  const ReferenceContactLog coarse = referenceContactLog(p, incoming, increments / 2);
  ExtrapolatedContactLog out;
  out.after = fine.after;
  for (const ReferenceStick& stick : fine.sticks) {
    if (stick.to_Ns - stick.from_Ns < shortest_Ns) continue;
    ExtrapolatedStick e{stick, std::numeric_limits<double>::infinity()};
    for (const ReferenceStick& partner : coarse.sticks) {
      const double change = stick.from_Ns - partner.from_Ns;
      if (partner.contact != stick.contact || std::abs(change) > shortest_Ns ||
          std::abs(change) >= e.onset_error_Ns)
        continue;
      e.stick.from_Ns = stick.from_Ns + change;  // fine + (fine - coarse)
      e.onset_error_Ns = std::abs(change);
    }
    out.sticks.push_back(e);
  }
  return out;
}

}  // namespace baize::physics::test
