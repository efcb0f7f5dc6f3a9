// Tests of the exact cushion solver's held laws: sliding contacts slide along their slips; a held
// contact sticks only while its cone holds it and otherwise slides along phi*, the direction in
// which its slip grows along itself (closed form, Newton's method and the search of the circle
// agree on it); the lag correction blends the directions by the given share, the lag of a slip
// growing from rest.
#include "physics/cushion_held_laws.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tests/physics/cushion_exact_parts_support.h"

namespace baize::physics {
namespace {

using cushion_exact::cross;
using cushion_exact::Friction;
using cushion_exact::HeldLaws;
using cushion_exact::Laws;
using cushion_exact::State;
using Held = test::Exposed<HeldLaws>;

// phi* is solved to 1e-10 rad (kCreepAngleTolerance): its slip rate's turn about it is that
// small against the rate (relative).
constexpr double kDirectionResidual = 1e-9;
constexpr double kRoundoff = 1e-13;

// Whether d is phi* of contact k under `laws` (contact k sliding along d): its slip rate lies
// along d and grows along it.
void expectGrowsAlongItself(const HeldLaws& impact, int k, Laws laws, const Eigen::Vector2d& d) {
  laws.stick[k] = false;
  laws.direction[k] = d;
  const Eigen::Vector2d rate = impact.slipRate(k, impact.frictionFor(laws));
  EXPECT_NEAR(d.norm(), 1, kRoundoff);
  EXPECT_LE(std::abs(cross(d, rate)), kDirectionResidual * rate.norm()) << k;
  EXPECT_GT(rate.dot(d), 0) << k;
}

TEST(CushionHeldLaws, SlidingContactsSlideAlongTheirSlips) {
  const CushionParams p = test::snookerCushion();
  const HeldLaws impact(p, test::spinningBall(p), test::partsOptions());
  const auto u = impact.slips(State::Zero());
  std::array<double, 2> speed{};
  const Laws laws = impact.lawsAt(u, &speed);
  for (int k = 0; k < 2; ++k) {
    EXPECT_FALSE(laws.stick[k]);
    EXPECT_NEAR((laws.direction[k] - u[k].normalized()).norm(), 0, kRoundoff);
    EXPECT_EQ(speed[k], u[k].norm());
  }
}

TEST(CushionHeldLaws, HeldClothSticksInsideItsConeAndElseSlidesAlongPhiStar) {
  // A ball rolling into the cushion holds its cloth contact; with sidespin and at other angles
  // the cone may or may not hold it. Either way the law must be consistent with the cone.
  const CushionParams p = test::snookerCushion();
  int stuck = 0, sliding = 0;
  for (double angle_deg : {10.0, 30.0, 50.0, 70.0, 90.0}) {
    for (double side : {-1.0, 0.0, 1.0}) {
      const double a = angle_deg * 3.14159265358979323846 / 180;
      Held impact(p, incomingBall(1.5, a, 1.5 / p.radius_m, side * 1.5 / p.radius_m),
                  test::partsOptions());
      impact.setContactMode(1, ContactMode::Stick);
      auto u = impact.slips(State::Zero());
      u[1].setZero();
      const Laws laws = impact.lawsAt(u, nullptr);
      if (laws.stick[1]) {
        ++stuck;
        EXPECT_GE(impact.coneMargin(1, impact.frictionFor(laws)), 0) << angle_deg;
        EXPECT_NEAR(impact.slipRate(1, impact.frictionFor(laws)).norm(), 0, kRoundoff);
      } else {
        ++sliding;
        expectGrowsAlongItself(impact, 1, laws, laws.direction[1]);
        // The stick law would need more friction than its cone gives.
        Laws sticking = laws;
        sticking.stick[1] = true;
        EXPECT_LT(impact.coneMargin(1, impact.frictionFor(sticking)), 0) << angle_deg;
      }
    }
  }
  EXPECT_GT(stuck + sliding, 0);
}

// For balls at 2 m/s with backspin and sidespin meeting the snooker cushion with nose friction
// mu_w at a few angles: check(impact, laws, angle_deg) with the nose held (its slip set aside)
// while the cloth slides along its slip, at the impact's start.
template <typename Check>
void forHeldNoseUnderSlidingCloth(double mu_w, const Check& check) {
  CushionParams p = test::snookerCushion();
  p.cushion_friction = mu_w;
  for (double angle_deg : {20.0, 45.0, 80.0}) {
    const double a = angle_deg * 3.14159265358979323846 / 180;
    Held impact(p, incomingBall(2.0, a, -1.0 / p.radius_m, 2.0 / p.radius_m), test::partsOptions());
    impact.setContactMode(0, ContactMode::Stick);
    const auto u = impact.slips(State::Zero());
    Laws laws;
    laws.stick = {true, false};
    laws.direction = {Eigen::Vector2d::UnitX(), u[1].normalized()};
    check(impact, laws, angle_deg);
  }
}

TEST(CushionHeldLaws, PhiStarOfTheNoseIsTheSameByEveryMethod) {
  // A slippery nose held while the cloth slides: the stick law needs a friction of about
  // s c / (s^2 + 5/2) = 0.14 of the normal impulse, beyond its cone.
  forHeldNoseUnderSlidingCloth(0.05, [](Held& impact, const Laws& laws, double angle_deg) {
    ASSERT_LT(impact.coneMargin(0, impact.frictionFor(laws)), 0) << angle_deg;
    const Eigen::Vector2d searched = impact.creepDirectionSearch(0, laws);
    expectGrowsAlongItself(impact, 0, laws, searched);
    Eigen::Vector2d newton;
    const Eigen::Vector2d guess =
        (searched + 0.05 * Eigen::Vector2d(-searched.y(), searched.x())).normalized();
    ASSERT_TRUE(impact.creepDirection(0, laws, guess, &newton)) << angle_deg;
    EXPECT_NEAR((newton - searched).norm(), 0, 1e-8) << angle_deg;
  });
}

TEST(CushionHeldLaws, TheSearchForAHeldNoseItsConeHoldsFindsNoGrowingDirection) {
  // A grippy nose held while the cloth slides: its cone holds it, so along no direction does its
  // slip grow along itself, and the search ends on the rate's mean over opposite directions.
  forHeldNoseUnderSlidingCloth(0.3, [](Held& impact, const Laws& laws, double angle_deg) {
    ASSERT_GT(impact.coneMargin(0, impact.frictionFor(laws)), 0) << angle_deg;
    Laws sliding = laws;
    sliding.stick[0] = false;
    auto rateAlong = [&](const Eigen::Vector2d& d) {
      sliding.direction[0] = d;
      return impact.slipRate(0, impact.frictionFor(sliding));
    };
    constexpr int kScan = 3600;  // no root of cross(d, r(d)) on a fine scan grows
    for (int i = 0; i < kScan; ++i) {
      const double phi = 2 * 3.14159265358979323846 * i / kScan;
      const Eigen::Vector2d d(std::cos(phi), std::sin(phi));
      constexpr double kNearRoot = 1e-3;  // of |r|: within a scan step of a root
      if (std::abs(cross(d, rateAlong(d))) < kNearRoot * rateAlong(d).norm()) {
        EXPECT_LE(rateAlong(d).dot(d), 0) << angle_deg << " deg, phi " << phi;
      }
    }
    const Eigen::Vector2d mean =
        (rateAlong(Eigen::Vector2d(1, 0)) + rateAlong(Eigen::Vector2d(-1, 0))).normalized();
    EXPECT_NEAR((impact.creepDirectionSearch(0, laws) - mean).norm(), 0, kRoundoff) << angle_deg;
  });
}

TEST(CushionHeldLaws, TheClothsRateWhileTheNoseSticksIsNotTakenAsAffine) {
  // While the nose sticks, its stick friction sets the cloth's normal force, so the cloth's slip
  // rate is rational in its direction's y component (and linear along x). It must not be taken as
  // affine, and the search must still find the direction that a fine scan finds.
  const CushionParams p = test::snookerCushion();
  int growing = 0;
  for (double angle_deg : {20.0, 45.0, 80.0}) {
    for (double side : {-2.0, 0.0, 2.0}) {
      const double a = angle_deg * 3.14159265358979323846 / 180;
      Held impact(p, incomingBall(2.0, a, -1.0 / p.radius_m, side / p.radius_m),
                  test::partsOptions());
      impact.setContactMode(0, ContactMode::Stick);
      impact.setContactMode(1, ContactMode::Stick);
      Laws laws;
      laws.stick = {true, true};
      laws.direction = {Eigen::Vector2d::UnitX(), Eigen::Vector2d::UnitX()};
      Laws sliding = laws;
      sliding.stick[1] = false;
      auto rateAlong = [&](const Eigen::Vector2d& d) {
        sliding.direction[1] = d;
        return impact.slipRate(1, impact.frictionFor(sliding));
      };
      const Eigen::Vector2d r0 = rateAlong(Eigen::Vector2d::Zero());
      const Eigen::Vector2d bend =
          rateAlong(Eigen::Vector2d::UnitY()) + rateAlong(-Eigen::Vector2d::UnitY()) - 2 * r0;
      EXPECT_GT(bend.norm(), kDirectionResidual * r0.norm()) << angle_deg << " deg, side " << side;
      Eigen::Vector2d affine_r0;
      Eigen::Matrix2d affine_W;
      EXPECT_FALSE(impact.affineSlipRate(1, laws, &affine_r0, &affine_W));
      // The fastest growth among the scan's near-roots of cross(d, r(d)).
      constexpr int kScan = 7200;
      constexpr double kNearRoot = 1e-3;  // of |r|: within a scan step of a root
      double best_growth = 0;
      for (int i = 0; i < kScan; ++i) {
        const double phi = 2 * 3.14159265358979323846 * i / kScan;
        const Eigen::Vector2d d(std::cos(phi), std::sin(phi));
        const Eigen::Vector2d r = rateAlong(d);
        if (std::abs(cross(d, r)) < kNearRoot * r.norm())
          best_growth = std::max(best_growth, r.dot(d));
      }
      if (best_growth <= 0) continue;
      ++growing;
      const Eigen::Vector2d searched = impact.creepDirectionSearch(1, laws);
      expectGrowsAlongItself(impact, 1, laws, searched);
      // The scan's best lies within a step of the root; its growth within that step's change.
      constexpr double kScanGrowthShare = 1e-2;
      EXPECT_GE(rateAlong(searched).dot(searched), (1 - kScanGrowthShare) * best_growth)
          << angle_deg << " deg, side " << side;
    }
  }
  EXPECT_GT(growing, 0);
}

TEST(CushionHeldLaws, LagCorrectionBlendsByTheShare) {
  const Eigen::Vector2d origin(1, 0), phi(0, 1);
  EXPECT_EQ(HeldLaws::lagCorrected(origin, phi, 0), origin);
  EXPECT_EQ(HeldLaws::lagCorrected(origin, phi, 1), phi);
  const Eigen::Vector2d half = HeldLaws::lagCorrected(origin, phi, 0.5);
  EXPECT_NEAR(half.x(), std::sqrt(0.5), kRoundoff);
  EXPECT_NEAR(half.y(), std::sqrt(0.5), kRoundoff);
  // 1 (no correction) where nothing restores or grows.
  EXPECT_EQ(HeldLaws::lagShareOf(0, 2, 1), 1);
  EXPECT_EQ(HeldLaws::lagShareOf(2, 0, 2), 1);
}

// The lag of a slip growing from rest behind phi* turning steadily at omega (rad per N s): the
// slip's direction theta follows d theta/dP = kappa (phi* - theta) / |u(P)|, so the lag l = phi* -
// theta solves l' = omega - kappa l / |u|, l(0) = 0: l(x) = omega int_0^x exp(-int_s^x kappa / |u|)
// ds, here by Simpson's rule on [0, x] (the integrand is smooth, concentrated within |u| / kappa of
// x). `exponent(s)` is int_s^x kappa / |u|.
template <typename Exponent>
double lagBehindSteadyTurn(double omega, double x, const Exponent& exponent) {
  constexpr int kIntervals = 200000;  // even; the integrand's width is >= 1e-3 x here
  const double h = x / kIntervals;
  double sum = 0;
  for (int i = 1; i <= kIntervals; ++i) {  // the integrand vanishes at s = 0
    const double weight = i == kIntervals ? 1 : (i % 2 == 1 ? 4 : 2);
    sum += weight * std::exp(-exponent(i * h));
  }
  return omega * sum * h / 3;
}

TEST(CushionHeldLaws, LagShareMatchesTheLagOfASlipGrowingFromRest) {
  const double kappa = 3, omega = 0.7, x = 0.01;  // restoring rate (m/s per N s), N s from rest
  for (double growth_over_kappa : {0.05, 0.1, 0.2}) {
    const double g = growth_over_kappa * kappa;  // the slip's growth rate now, d|u|/dP
    // Growing linearly, |u| = g s: the share is exact.
    const double linear_lag =
        lagBehindSteadyTurn(omega, x, [&](double s) { return kappa / g * std::log(x / s); });
    constexpr double kQuadratureError = 1e-9;  // the lag's integral, taken numerically
    EXPECT_NEAR(1 - linear_lag / (omega * x), HeldLaws::lagShareOf(g, kappa, 1), kQuadratureError);
    // Growing from a zero rate, |u| = a s^2 with g = 2 a x: the share matches the lag to second
    // order in g / kappa: its relative error is about 0.3 to 0.45 of (g / kappa)^2 here.
    constexpr double kSecondOrderErrorFactor = 0.6;
    const double a = g / (2 * x);
    const double from_edge_lag =
        lagBehindSteadyTurn(omega, x, [&](double s) { return kappa / a * (1 / s - 1 / x); });
    const double share_lag = (1 - HeldLaws::lagShareOf(g, kappa, 2)) * omega * x;
    EXPECT_LT(std::abs(share_lag / from_edge_lag - 1),
              kSecondOrderErrorFactor * growth_over_kappa * growth_over_kappa)
        << growth_over_kappa;
  }
}

}  // namespace
}  // namespace baize::physics
