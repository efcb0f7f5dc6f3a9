#include "physics/ball_ball_impact.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/physics/fp_trap_support.h"
#include "tests/physics/rejection_test_support.h"

namespace baize::physics {
namespace {

using Eigen::Vector3d;
using test::expectValueRejected;
using ::testing::HasSubstr;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180;

// Tolerances. "Relative" means relative to the speed scale of the impact (largest |v| or R |w|).
// Closed-form model (FrictionalInelastic): a handful of operations, so a few ulp of the scale.
constexpr double kAlgebraicRelative = 1e-13;
// Mathavan2014 at the default tolerance (1e-11 per step): measured worst 1.2e-11 against a 1e-14
// run over 2000 random impacts; 1e-9 leaves room for the step sequence to differ between runs.
constexpr double kIntegratedRelative = 1e-9;
// Energy may stay equal (e = 1, no friction) up to round-off, never grow beyond it.
constexpr double kEnergyRoundoffRelative = 1e-12;
// Measured snooker shots (physics-notes section 3) against the Mathavan model, m/s: the combined
// uncertainty of speeds read from high-speed video after the balls settle into rolling (a few
// frames, cm/s level) and of a rigid point-contact model; the notes' cushion data carry +-0.03.
constexpr double kMeasuredSpeedTolerance = 0.05;
// Published model values are printed to 3 significant figures (1.28 m/s) and 0.01 deg; the
// paper's Euler scheme (N = 1000 per impulse) adds about 1e-4 m/s.
constexpr double kPublishedSpeedTolerance = 0.005;  // m/s
constexpr double kPublishedAngleTolerance = 0.05;   // deg

BallVelocity ballOf(const Vector3d& v, const Vector3d& w) {
  BallVelocity b;
  b.v = v;
  b.w = w;
  return b;
}

double kineticEnergy(const BallBallParams& p, const BallVelocity& b1, const BallVelocity& b2) {
  const double R2 = p.radius_m * p.radius_m;
  return 0.5 * p.mass1_kg * b1.v.squaredNorm() + 0.2 * p.mass1_kg * R2 * b1.w.squaredNorm() +
         0.5 * p.mass2_kg * b2.v.squaredNorm() + 0.2 * p.mass2_kg * R2 * b2.w.squaredNorm();
}

Vector3d momentum(const BallBallParams& p, const BallVelocity& b1, const BallVelocity& b2) {
  return p.mass1_kg * b1.v + p.mass2_kg * b2.v;
}

double speedScale(const BallBallParams& p, const BallVelocity& b1, const BallVelocity& b2) {
  const double R = p.radius_m;
  return std::max({b1.v.norm(), b2.v.norm(), R * b1.w.norm(), R * b2.w.norm()});
}

// Velocity a ball ends with once cloth friction has made it roll (physics-notes section 2):
// v = (5/7) v0 + (2/7) R (w0 x z), whatever the cloth friction is.
Vector3d rolledVelocity(const BallVelocity& b, double radius_m) {
  return (5.0 / 7.0) * b.v + (2.0 / 7.0) * radius_m * b.w.cross(Vector3d::UnitZ());
}

// A ball rolling without slip on the cloth with velocity v: w = z x v / R.
BallVelocity rollingBall(const Vector3d& v, double radius_m) {
  return ballOf(v, Vector3d::UnitZ().cross(v) / radius_m);
}

double maxStateDifference(const BallBallImpactResult& a, const BallBallImpactResult& b, double R) {
  return std::max({(a.ball1.v - b.ball1.v).norm(), (a.ball2.v - b.ball2.v).norm(),
                   R * (a.ball1.w - b.ball1.w).norm(), R * (a.ball2.w - b.ball2.w).norm()});
}

// Portable uniform numbers in [-1, 1) from the standard-defined mt19937_64 sequence.
struct Random {
  std::mt19937_64 engine;
  explicit Random(std::uint64_t seed) : engine(seed) {}
  double uniform() { return static_cast<double>(engine() >> 11) * 0x1.0p-52 - 1.0; }
};

struct Impact {
  BallVelocity b1, b2;
  Vector3d n;
};

// Random approaching pair on the table: speeds up to 3 and 1.5 m/s, spins up to 120 and 60 rad/s
// (R w up to about 3.4 m/s for pool balls), any line of centres, approach speed at least 1 cm/s.
std::vector<Impact> randomImpacts(std::uint64_t seed, int count) {
  Random r(seed);
  std::vector<Impact> out;
  while (static_cast<int>(out.size()) < count) {
    Impact i;
    i.b1 = ballOf({3 * r.uniform(), 3 * r.uniform(), 0},
                  120 * Vector3d(r.uniform(), r.uniform(), r.uniform()));
    i.b2 = ballOf({1.5 * r.uniform(), 1.5 * r.uniform(), 0},
                  60 * Vector3d(r.uniform(), r.uniform(), r.uniform()));
    const double angle = kPi * r.uniform();
    i.n = {std::cos(angle), std::sin(angle), 0};
    if (approachSpeed(i.b1, i.b2, i.n) < 0) i.n = -i.n;
    if (approachSpeed(i.b1, i.b2, i.n) < 0.01) continue;
    out.push_back(i);
  }
  return out;
}

BallBallParams frictionless(BallBallParams p, double restitution) {
  p.restitution = restitution;
  p.friction_law = BallBallFrictionLaw::Constant;
  p.constant_friction = 0;
  p.ball_friction = 0;
  p.cloth_friction = 0;
  return p;
}

BallBallParams poolParams() { return BallBallParams{}; }

BallBallParams poolMathavanParams() {
  BallBallParams p;
  p.model = BallBallModel::Mathavan2014;
  p.restitution = 0.95;
  return p;
}

std::vector<BallBallParams> bothModels() {
  BallBallParams unequal_alciatore = poolParams();
  unequal_alciatore.mass2_kg = 0.21;  // heavier object ball, as in some bar-box sets
  BallBallParams unequal_mathavan = snookerMathavan2014Params();
  unequal_mathavan.mass1_kg = 0.12;
  return {poolParams(), unequal_alciatore, snookerMathavan2014Params(), unequal_mathavan,
          poolMathavanParams()};
}

double relativeTolerance(const BallBallParams& p) {
  return p.model == BallBallModel::FrictionalInelastic ? kAlgebraicRelative : kIntegratedRelative;
}

// ---------------------------------------------------------------------------------------------
// Conservation and dissipation

TEST(BallBallImpact, FrictionalInelasticConservesPlanarMomentum) {
  for (const BallBallParams& p : bothModels()) {
    if (p.model != BallBallModel::FrictionalInelastic) continue;
    for (const Impact& i : randomImpacts(11, 2000)) {
      const auto r = resolveBallBallImpact(p, i.b1, i.b2, i.n);
      const double scale = (p.mass1_kg + p.mass2_kg) * speedScale(p, i.b1, i.b2);
      EXPECT_LE((momentum(p, r.ball1, r.ball2) - momentum(p, i.b1, i.b2)).norm(),
                kAlgebraicRelative * scale);
    }
  }
}

TEST(BallBallImpact, MathavanConservesPlanarMomentumWithoutClothFriction) {
  BallBallParams p = snookerMathavan2014Params();
  p.cloth_friction = 0;
  for (const Impact& i : randomImpacts(12, 300)) {
    const auto r = resolveBallBallImpact(p, i.b1, i.b2, i.n);
    const double scale = (p.mass1_kg + p.mass2_kg) * speedScale(p, i.b1, i.b2);
    // Linear invariants survive Runge-Kutta steps exactly, so only round-off is left.
    EXPECT_LE((momentum(p, r.ball1, r.ball2) - momentum(p, i.b1, i.b2)).norm(),
              kAlgebraicRelative * 10 * scale);
  }
}

TEST(BallBallImpact, MathavanMomentumChangesOnlyByClothFriction) {
  const BallBallParams p = snookerMathavan2014Params();
  int loaded = 0;
  for (const Impact& i : randomImpacts(13, 300)) {
    const auto r = resolveBallBallImpact(p, i.b1, i.b2, i.n);
    const double table = r.table_normal_impulse_Ns[0] + r.table_normal_impulse_Ns[1];
    loaded += table > 0;
    const double scale = (p.mass1_kg + p.mass2_kg) * speedScale(p, i.b1, i.b2);
    // Coulomb: the cloth's friction impulse is at most mu_s times the table's normal impulse, which
    // is at most mu_b times the ball-ball normal impulse.
    EXPECT_LE((momentum(p, r.ball1, r.ball2) - momentum(p, i.b1, i.b2)).norm(),
              p.cloth_friction * table + kIntegratedRelative * scale);
    EXPECT_LE(table, p.ball_friction * r.normal_impulse_Ns * (1 + kIntegratedRelative));
  }
  EXPECT_GT(loaded, 250);  // random spins almost always have a vertical slip part
}

TEST(BallBallImpact, KineticEnergyNeverGrows) {
  std::uint64_t seed = 100;
  for (BallBallParams p : bothModels()) {
    for (double e : {p.restitution, 1.0}) {
      p.restitution = e;
      const int count = p.model == BallBallModel::FrictionalInelastic ? 3000 : 1000;
      for (const Impact& i : randomImpacts(++seed, count)) {
        const auto r = resolveBallBallImpact(p, i.b1, i.b2, i.n);
        const double before = kineticEnergy(p, i.b1, i.b2);
        EXPECT_LE(kineticEnergy(p, r.ball1, r.ball2), before * (1 + kEnergyRoundoffRelative));
        EXPECT_EQ(r.ball1.v.z(), 0.0);
        EXPECT_EQ(r.ball2.v.z(), 0.0);
      }
    }
  }
}

// Both models (and the Euler reference scheme) with floating-point exceptions trapped, on random
// impacts and on the edges where a direction is undefined: contact slip exactly zero (a stun shot
// head on, two balls rolling with matching surfaces), no friction, e = 0, slow approach, and a
// slip that has no horizontal or no vertical part. No path may divide by a zero slip speed or
// produce a NaN; energy still never grows.
TEST(BallBallImpact, NoFloatingPointExceptionEvenWhereTheSlipIsExactlyZero) {
  std::vector<Impact> impacts = randomImpacts(211, 300);
  const Vector3d x = Vector3d::UnitX();
  const double R = poolParams().radius_m;
  impacts.push_back(
      {ballOf({2, 0, 0}, Vector3d::Zero()), ballOf(Vector3d::Zero(), Vector3d::Zero()), x});
  impacts.push_back({rollingBall({2, 0, 0}, R), rollingBall({0.5, 0, 0}, R), x});
  // Slip purely vertical (topspin only, head on) and purely horizontal (sidespin only).
  impacts.push_back({ballOf({1, 0, 0}, {0, 30, 0}), ballOf(Vector3d::Zero(), Vector3d::Zero()), x});
  impacts.push_back({ballOf({1, 0, 0}, {0, 0, 30}), ballOf(Vector3d::Zero(), Vector3d::Zero()), x});
  // Approaching at 1 um/s: the impulses are tiny but must stay finite.
  impacts.push_back(
      {ballOf({1e-6, 0, 0}, Vector3d::Zero()), ballOf(Vector3d::Zero(), Vector3d::Zero()), x});
  std::vector<BallBallParams> models = bothModels();
  for (const BallBallParams& p : bothModels()) {
    models.push_back(frictionless(p, 1.0));
    models.push_back(frictionless(p, 0.0));
  }
  BallBallParams euler = poolMathavanParams();
  euler.fixed_steps = 200;
  models.push_back(euler);
  for (const BallBallParams& p : models) {
    for (const Impact& i : impacts) {
      BallBallImpactResult r;
      {
        test::FloatingPointTraps traps;
        r = resolveBallBallImpact(p, i.b1, i.b2, i.n);
      }
      EXPECT_TRUE(r.ball1.v.allFinite() && r.ball1.w.allFinite() && r.ball2.v.allFinite() &&
                  r.ball2.w.allFinite());
      if (p.fixed_steps == 0) {
        EXPECT_LE(kineticEnergy(p, r.ball1, r.ball2),
                  kineticEnergy(p, i.b1, i.b2) * (1 + kEnergyRoundoffRelative));
      }
    }
  }
}

TEST(BallBallImpact, FrictionlessElasticHeadOnExchangesVelocities) {
  for (BallBallParams p : {poolParams(), snookerMathavan2014Params()}) {
    p = frictionless(p, 1.0);
    const BallVelocity b1 = ballOf({1.3, 0.4, 0}, {5, -7, 20});
    const BallVelocity b2 = ballOf({-0.2, 0.4, 0}, {-3, 2, 1});
    const auto r = resolveBallBallImpact(p, b1, b2, Vector3d::UnitX());
    const double tol = relativeTolerance(p) * speedScale(p, b1, b2);
    EXPECT_LE((r.ball1.v - b2.v).norm(), tol);
    EXPECT_LE((r.ball2.v - b1.v).norm(), tol);
    EXPECT_LE(p.radius_m * (r.ball1.w - b1.w).norm(), tol);  // no friction: spins untouched
    EXPECT_LE(p.radius_m * (r.ball2.w - b2.w).norm(), tol);
  }
}

TEST(BallBallImpact, FrictionlessEnergeticRestitutionEqualsNewtons) {
  // Without friction the energetic criterion gives g_n' = -e g_n, whatever the masses.
  for (double e : {0.0, 0.3, 0.89, 1.0}) {
    BallBallParams p = frictionless(snookerMathavan2014Params(), e);
    p.mass2_kg = 0.2;
    const BallVelocity b1 = ballOf({1.0, 0.5, 0}, {10, 20, 30});
    const BallVelocity b2 = ballOf({0.1, -0.3, 0}, {0, 0, -5});
    const Vector3d n(std::cos(0.4), std::sin(0.4), 0);
    const auto r = resolveBallBallImpact(p, b1, b2, n);
    const double g_n = approachSpeed(b1, b2, n);
    EXPECT_NEAR(approachSpeed(r.ball1, r.ball2, n), -e * g_n, kIntegratedRelative * g_n) << e;
    const double mu_red = p.mass1_kg * p.mass2_kg / (p.mass1_kg + p.mass2_kg);
    EXPECT_NEAR(r.normal_impulse_Ns, (1 + e) * mu_red * g_n, kIntegratedRelative * mu_red * g_n);
    // A grazing contact (approach 1e-7 of the speed scale) is resolved just as finely.
    const BallVelocity grazing = ballOf({1e-7, 1.0, 0}, {10, 20, 30});
    const auto g = resolveBallBallImpact(p, grazing, BallVelocity{}, Vector3d::UnitX());
    EXPECT_NEAR(approachSpeed(g.ball1, g.ball2, Vector3d::UnitX()), -e * 1e-7,
                kIntegratedRelative * 1e-7);
  }
}

// ---------------------------------------------------------------------------------------------
// Known behaviour

TEST(BallBallImpact, ThirtyDegreeRuleForRollingCueBall) {
  // Frictionless elastic balls, rolling cue ball on a stationary object ball: the cue ball's path
  // once it rolls again deflects at most about 33.7 deg, near a cut of about 28 deg.
  const BallBallParams p = frictionless(poolParams(), 1.0);
  const double R = p.radius_m;
  double best_deflection = 0, best_cut = 0;
  for (double cut_deg = 0.5; cut_deg < 89.5; cut_deg += 0.05) {
    const double cut = cut_deg * kDeg;
    const BallVelocity cue = rollingBall({1.2, 0, 0}, R);
    const auto r =
        resolveBallBallImpact(p, cue, BallVelocity{}, {std::cos(cut), -std::sin(cut), 0});
    const Vector3d final_velocity = rolledVelocity(r.ball1, R);
    // The object ball goes off to the right (-y), so the cue ball turns left (+y).
    const double deflection = std::atan2(final_velocity.y(), final_velocity.x()) / kDeg;
    if (deflection > best_deflection) best_deflection = deflection, best_cut = cut_deg;
  }
  EXPECT_NEAR(best_deflection, 33.7, 0.1);  // deg; the notes quote 33.7 (exact: 33.75)
  EXPECT_NEAR(best_cut, 28.0, 0.5);         // deg; the notes quote about 28 (exact: 28.1)
}

// Object ball's direction relative to the line of centres, deg, positive towards the side the cue
// ball's tangential velocity points to.
double throwAngleDeg(const BallBallImpactResult& r, const Vector3d& n, const Vector3d& cue_v) {
  const Vector3d t = Vector3d::UnitZ().cross(n);
  const double side = cue_v.dot(t) >= 0 ? 1 : -1;
  return std::atan2(side * r.ball2.v.dot(t), r.ball2.v.dot(n)) / kDeg;
}

TEST(BallBallImpact, SlowStunHalfBallHitThrowsTheObjectBall) {
  const BallBallParams p = poolParams();
  const Vector3d n(std::cos(30 * kDeg), -std::sin(30 * kDeg), 0);  // half-ball: 30 deg cut
  auto throwAt = [&](double speed) {
    const BallVelocity cue = ballOf({speed, 0, 0}, Vector3d::Zero());  // stun: no spin at contact
    return throwAngleDeg(resolveBallBallImpact(p, cue, BallVelocity{}, n), n, cue.v);
  };
  const double slow = throwAt(0.5), medium = throwAt(1.5), fast = throwAt(4.0);
  EXPECT_GT(slow, 0.5);  // deg; Alciatore's measurements: up to about 5 deg for slow stun hits
  EXPECT_LT(slow, 6.0);
  EXPECT_GT(medium, 0.0);
  EXPECT_LT(medium, slow);  // friction falls with slip speed, so throw falls with speed
  EXPECT_LT(fast, medium);
  EXPECT_GT(fast, 0.0);
}

TEST(BallBallImpact, FollowReducesThrowInBothModels) {
  // The cue ball's topspin makes the slip mostly vertical, so less friction acts sideways.
  for (const BallBallParams& p : {poolParams(), snookerMathavan2014Params()}) {
    const double R = p.radius_m;
    const Vector3d n(std::cos(30 * kDeg), -std::sin(30 * kDeg), 0);
    const BallVelocity stun = ballOf({1.0, 0, 0}, Vector3d::Zero());
    const BallVelocity follow = rollingBall({1.0, 0, 0}, R);
    const double stun_throw =
        throwAngleDeg(resolveBallBallImpact(p, stun, BallVelocity{}, n), n, stun.v);
    const double roll_throw =
        throwAngleDeg(resolveBallBallImpact(p, follow, BallVelocity{}, n), n, follow.v);
    EXPECT_GT(stun_throw, 0.5);
    EXPECT_LT(stun_throw, 6.0);
    EXPECT_GT(roll_throw, 0.0);
    EXPECT_LT(roll_throw, stun_throw);
  }
}

TEST(BallBallImpact, AlciatoreFrictionLaw) {
  const BallBallParams p = poolParams();
  EXPECT_NEAR(ballBallFriction(p, 0.0), 9.951e-3 + 0.108, 1e-15);
  EXPECT_NEAR(ballBallFriction(p, 1.0), 9.951e-3 + 0.108 * std::exp(-1.088), 1e-15);
  EXPECT_NEAR(ballBallFriction(p, 100.0), 9.951e-3, 1e-15);
  BallBallParams constant = p;
  constant.friction_law = BallBallFrictionLaw::Constant;
  constant.constant_friction = 0.07;
  EXPECT_EQ(ballBallFriction(constant, 3.0), 0.07);
}

TEST(BallBallImpact, FrictionalInelasticCapLeavesFreeBodySlipZero) {
  // A large constant friction so that the cap applies; rolling cue ball, so the slip is mostly
  // vertical. As free bodies the contact points end with no slip; the vertical velocities the
  // friction gave are then removed, which leaves exactly their difference as vertical slip.
  BallBallParams p = poolParams();
  p.friction_law = BallBallFrictionLaw::Constant;
  p.constant_friction = 0.3;
  const Vector3d n(std::cos(10 * kDeg), std::sin(10 * kDeg), 0);
  const BallVelocity cue = rollingBall({1.5, 0, 0}, p.radius_m);
  const auto r = resolveBallBallImpact(p, cue, BallVelocity{}, n);
  ASSERT_TRUE(r.contact_rolling_from_impulse_Ns.has_value());
  const Vector3d slip = contactSlip(p, r.ball1, r.ball2, n);
  const double removed =
      r.discarded_vertical_velocity_mps[0] - r.discarded_vertical_velocity_mps[1];
  EXPECT_LE((slip + removed * Vector3d::UnitZ()).norm(), kAlgebraicRelative * 1.5);
  EXPECT_GT(removed, 0.0);  // topspin: friction lifts the cue ball and presses the object ball down
  EXPECT_GT(r.table_normal_impulse_Ns[1], 0.0);
  EXPECT_EQ(r.table_normal_impulse_Ns[0], 0.0);
}

TEST(BallBallImpact, MathavanContactRollsOnceItsSlipVanishes) {
  // Stun, nearly full hit: the small sideways slip is used up early; from then on the contact
  // rolls.
  const BallBallParams p = snookerMathavan2014Params();
  const Vector3d n(std::cos(5 * kDeg), -std::sin(5 * kDeg), 0);
  const BallVelocity cue = ballOf({1.0, 0, 0}, Vector3d::Zero());
  const auto r = resolveBallBallImpact(p, cue, BallVelocity{}, n);
  ASSERT_TRUE(r.contact_rolling_from_impulse_Ns.has_value());
  EXPECT_GT(*r.contact_rolling_from_impulse_Ns, 0.0);
  EXPECT_LT(*r.contact_rolling_from_impulse_Ns, r.normal_impulse_Ns);
  EXPECT_LE(contactSlip(p, r.ball1, r.ball2, n).norm(), kIntegratedRelative);
  // No spin about the tangent: no vertical friction, so the table plays no part.
  EXPECT_EQ(r.table_normal_impulse_Ns[0], 0.0);
  EXPECT_EQ(r.table_normal_impulse_Ns[1], 0.0);
}

TEST(BallBallImpact, MathavanRollingCueBallPressesTheObjectBallIntoTheCloth) {
  // Head-on rolling cue ball: its contact point moves down, so friction lifts the cue ball and
  // presses the object ball down; only the object ball takes a table reaction, and its cloth slip
  // points along +n throughout (it starts at rest and is pushed forward), so the cloth changes the
  // pair's momentum by exactly -mu_s N2 n. (The measured shots below cannot see this: cloth
  // friction never changes the velocity a ball ends with once it rolls.)
  const BallBallParams p = snookerMathavan2014Params();
  const BallVelocity cue = rollingBall({1.2, 0, 0}, p.radius_m);
  const auto r = resolveBallBallImpact(p, cue, BallVelocity{}, Vector3d::UnitX());
  EXPECT_EQ(r.table_normal_impulse_Ns[0], 0.0);
  EXPECT_GT(r.table_normal_impulse_Ns[1], 0.0);
  EXPECT_GT(r.discarded_vertical_velocity_mps[0], 0.0);  // the cue ball would hop
  EXPECT_NEAR(r.discarded_vertical_velocity_mps[1], -r.table_normal_impulse_Ns[1] / p.mass2_kg,
              1e-15);
  // While slipping, the vertical friction is mu_b per unit normal impulse (the slip is vertical).
  EXPECT_NEAR(r.table_normal_impulse_Ns[1], p.ball_friction * r.normal_impulse_Ns,
              kIntegratedRelative * r.normal_impulse_Ns);
  const Vector3d change = momentum(p, r.ball1, r.ball2) - momentum(p, cue, BallVelocity{});
  const Vector3d expected = -p.cloth_friction * r.table_normal_impulse_Ns[1] * Vector3d::UnitX();
  EXPECT_LE((change - expected).norm(), kIntegratedRelative * p.mass1_kg * 1.2);
  // The object ball leaves with backspin from the downward friction at its back (w_y < 0 while
  // rolling forward along +x would need w_y > 0).
  EXPECT_LT(r.ball2.w.y(), 0.0);
}

TEST(BallBallImpact, ModelsAgreeWithoutSpinAboutTheTangent) {
  // With w_t = 0 on both balls the slip stays horizontal, the table takes no impulse, friction is
  // mu_b until the slip vanishes, and the energetic and Newton restitutions coincide: the Mathavan
  // integration must then equal the algebraic model with constant mu = mu_b.
  const BallBallParams mathavan = snookerMathavan2014Params();
  BallBallParams algebraic = mathavan;
  algebraic.model = BallBallModel::FrictionalInelastic;
  algebraic.friction_law = BallBallFrictionLaw::Constant;
  algebraic.constant_friction = mathavan.ball_friction;
  Random rng(7);
  int capped = 0;
  for (int k = 0; k < 200; ++k) {
    const Vector3d n(1, 0, 0);  // frame in which w_t is w_y
    const BallVelocity b1 =
        ballOf({1 + rng.uniform(), rng.uniform(), 0}, {50 * rng.uniform(), 0, 80 * rng.uniform()});
    const BallVelocity b2 = ballOf({0.5 * rng.uniform(), rng.uniform(), 0},
                                   {50 * rng.uniform(), 0, 80 * rng.uniform()});
    if (approachSpeed(b1, b2, n) < 0.05) continue;
    const auto a = resolveBallBallImpact(algebraic, b1, b2, n);
    const auto m = resolveBallBallImpact(mathavan, b1, b2, n);
    capped += a.contact_rolling_from_impulse_Ns.has_value();
    EXPECT_LE(maxStateDifference(a, m, mathavan.radius_m),
              kIntegratedRelative * speedScale(mathavan, b1, b2));
    EXPECT_EQ(m.table_normal_impulse_Ns[0] + m.table_normal_impulse_Ns[1], 0.0);
  }
  EXPECT_GT(capped, 10);  // both branches (slip used up, or not) are exercised
}

// ---------------------------------------------------------------------------------------------
// Symmetries

// Reflection in the vertical plane x = 0: polar vectors flip x, axial vectors (spins) flip y and z.
Vector3d mirrorPolar(const Vector3d& v) { return {-v.x(), v.y(), v.z()}; }
Vector3d mirrorAxial(const Vector3d& w) { return {w.x(), -w.y(), -w.z()}; }
BallVelocity mirror(const BallVelocity& b) { return ballOf(mirrorPolar(b.v), mirrorAxial(b.w)); }

TEST(BallBallImpact, MirrorSymmetry) {
  for (const BallBallParams& p : bothModels()) {
    for (const Impact& i : randomImpacts(21, 200)) {
      const auto r = resolveBallBallImpact(p, i.b1, i.b2, i.n);
      const auto m = resolveBallBallImpact(p, mirror(i.b1), mirror(i.b2), mirrorPolar(i.n));
      BallBallImpactResult expected = r;
      expected.ball1 = mirror(r.ball1);
      expected.ball2 = mirror(r.ball2);
      EXPECT_LE(maxStateDifference(m, expected, p.radius_m),
                relativeTolerance(p) * speedScale(p, i.b1, i.b2));
    }
  }
}

TEST(BallBallImpact, SwappingLabelsGivesTheSamePhysics) {
  for (const BallBallParams& p : bothModels()) {
    BallBallParams swapped = p;
    std::swap(swapped.mass1_kg, swapped.mass2_kg);
    for (const Impact& i : randomImpacts(22, 200)) {
      const auto r = resolveBallBallImpact(p, i.b1, i.b2, i.n);
      const auto s = resolveBallBallImpact(swapped, i.b2, i.b1, -i.n);
      BallBallImpactResult expected = r;
      expected.ball1 = r.ball2;
      expected.ball2 = r.ball1;
      EXPECT_LE(maxStateDifference(s, expected, p.radius_m),
                relativeTolerance(p) * speedScale(p, i.b1, i.b2));
      EXPECT_NEAR(s.normal_impulse_Ns, r.normal_impulse_Ns,
                  relativeTolerance(p) * r.normal_impulse_Ns);
    }
  }
}

TEST(BallBallImpact, MathavanIsLinearInTheIncomingVelocities) {
  // No speed enters the model except through the state, so scaling every velocity and spin by
  // lambda scales every outgoing one by lambda (Alciatore's speed-dependent mu breaks this).
  const BallBallParams p = snookerMathavan2014Params();
  constexpr double lambda = 2.7;
  for (const Impact& i : randomImpacts(23, 100)) {
    const auto r = resolveBallBallImpact(p, i.b1, i.b2, i.n);
    const auto s = resolveBallBallImpact(p, ballOf(lambda * i.b1.v, lambda * i.b1.w),
                                         ballOf(lambda * i.b2.v, lambda * i.b2.w), i.n);
    BallBallImpactResult expected = r;
    expected.ball1 = ballOf(lambda * r.ball1.v, lambda * r.ball1.w);
    expected.ball2 = ballOf(lambda * r.ball2.v, lambda * r.ball2.w);
    EXPECT_LE(maxStateDifference(s, expected, p.radius_m),
              kIntegratedRelative * lambda * speedScale(p, i.b1, i.b2));
  }
}

// ---------------------------------------------------------------------------------------------
// Grazing contacts at ball speeds

// Rate evaluations a grazing Mathavan impact may take: its rates hardly change over its tiny
// impulse, so the adaptive solver needs a few steps of 12 evaluations (measured 62 with the
// Dormand-Prince 8(5,3) pair, 106 with the 5(4) pair before it, about what a head-on impact takes);
// before the fix it ran out of its 200000 steps.
constexpr long kGrazingAdaptiveEvaluations = 200;
// Increments of the paper's Euler scheme used on grazing impacts, and how late (in increments) it
// may end: each of its two ends (compression, restitution) is detected up to one increment late.
constexpr int kGrazingEulerSteps = 1000;
constexpr double kEulerLateIncrements = 2;

// Two balls at m/s with strong spin (also about the tangent, so the table and cloth friction act)
// whose normal velocities differ by only approach_mps: both are about 1 m/s along
// n = (~1, approach_mps / 2, 0), so v1n - v2n cancels to round-off (or to zero) while
// (v1 - v2) . n = (0, 2, 0) . n is exactly approach_mps.
Impact grazingImpact(double approach_mps) {
  const double s = approach_mps / 2;
  Impact i;
  i.b1 = ballOf({1, 1, 0}, {50, -80, 60});
  i.b2 = ballOf({1, -1, 0}, {-30, 70, 20});
  i.n = {std::sqrt(1 - s * s), s, 0};
  return i;
}

const double kGrazingApproaches_mps[] = {1e-9, 1e-15, 1e-30, 1e-100};

TEST(BallBallImpact, MathavanResolvesGrazingContactsAtBallSpeeds) {
  // Regression (found by fuzzing): the compression was tracked through v1n - v2n, which cancels
  // to the ball speeds' round-off, so at 1e-30 and 1e-100 m/s the integration never saw the
  // approach end and exhausted its step budget (std::logic_error), and at 1e-9 and 1e-15 m/s it
  // ended at the wrong impulse. g_n is now a state of its own, with its error measured against
  // the approach.
  const BallBallParams p = snookerMathavan2014Params();
  const double e = p.restitution;
  const double mu_red = p.mass1_kg * p.mass2_kg / (p.mass1_kg + p.mass2_kg);
  const double friction_product = p.cloth_friction * p.ball_friction;
  std::vector<double> compression_per_approach;
  for (double approach : kGrazingApproaches_mps) {
    const Impact i = grazingImpact(approach);
    ASSERT_EQ(approachSpeed(i.b1, i.b2, i.n), approach);
    BallBallImpactResult r;
    {
      test::FloatingPointTraps traps;
      r = resolveBallBallImpact(p, i.b1, i.b2, i.n);
    }
    EXPECT_LE(r.rhs_evaluations, kGrazingAdaptiveEvaluations) << approach;
    EXPECT_LE(kineticEnergy(p, r.ball1, r.ball2),
              kineticEnergy(p, i.b1, i.b2) * (1 + kEnergyRoundoffRelative))
        << approach;
    // dg_n/dP lies within (1 +- mu_s mu_b) / mu* (derivation in ball_ball_impact.cpp), so the
    // compression ends at an impulse of about mu* times the approach.
    EXPECT_GE(r.compression_impulse_Ns, mu_red * approach / (1 + friction_product)) << approach;
    EXPECT_LE(r.compression_impulse_Ns, mu_red * approach / (1 - friction_product)) << approach;
    // Over so small an impulse the rates are constant: g_n falls linearly, so the compression work
    // is approach * P_c / 2 and the energetic restitution ends at P = (1 + e) P_c, where
    // g_n = -e * approach.
    EXPECT_NEAR(2 * r.compression_work_J / (r.compression_impulse_Ns * approach), 1.0,
                kIntegratedRelative)
        << approach;
    EXPECT_NEAR(r.normal_impulse_Ns / r.compression_impulse_Ns, 1 + e, kIntegratedRelative)
        << approach;
    compression_per_approach.push_back(r.compression_impulse_Ns / approach);
    // The velocities change by no more than the impulses allow (normal P, ball friction mu_b P,
    // cloth friction mu_s mu_b P), plus round-off of the ball speeds.
    const double impulse_bound = (1 + p.ball_friction + friction_product) * r.normal_impulse_Ns;
    const double roundoff = kAlgebraicRelative * speedScale(p, i.b1, i.b2);
    EXPECT_LE((r.ball1.v - i.b1.v).norm(), impulse_bound / p.mass1_kg + roundoff) << approach;
    EXPECT_LE((r.ball2.v - i.b2.v).norm(), impulse_bound / p.mass2_kg + roundoff) << approach;
  }
  // Linear in the approach: the same impulse per m/s of approach at every scale.
  for (double c : compression_per_approach) {
    EXPECT_NEAR(c / compression_per_approach[0], 1.0, kIntegratedRelative);
  }
}

TEST(BallBallImpact, PaperEulerSchemeResolvesGrazingContactsAtBallSpeeds) {
  // Regression (as above): the Euler scheme's end of compression, tested on v1n - v2n, came at
  // once (cancelled to zero) or never (std::logic_error after 1000 times its increments).
  const BallBallParams adaptive = snookerMathavan2014Params();
  BallBallParams euler = adaptive;
  euler.fixed_steps = kGrazingEulerSteps;
  const double mu_red =
      adaptive.mass1_kg * adaptive.mass2_kg / (adaptive.mass1_kg + adaptive.mass2_kg);
  for (double approach : kGrazingApproaches_mps) {
    const Impact i = grazingImpact(approach);
    BallBallImpactResult r, reference;
    {
      test::FloatingPointTraps traps;
      r = resolveBallBallImpact(euler, i.b1, i.b2, i.n);
      reference = resolveBallBallImpact(adaptive, i.b1, i.b2, i.n);
    }
    const double increment_Ns = (1 + euler.restitution) * mu_red * approach / kGrazingEulerSteps;
    EXPECT_NEAR(r.compression_impulse_Ns, reference.compression_impulse_Ns,
                kEulerLateIncrements * increment_Ns)
        << approach;
    EXPECT_NEAR(r.normal_impulse_Ns, reference.normal_impulse_Ns,
                kEulerLateIncrements * increment_Ns)
        << approach;
  }
}

TEST(BallBallImpact, FrictionalInelasticNormalImpulseComesFromTheApproachOnGrazingContacts) {
  // Newton's law on the approach itself: P = mu* (1 + e) (v1 - v2) . n, even where v1n - v2n
  // cancels (before the fix, to zero at 1e-30 m/s: no impulse at all).
  const BallBallParams p = poolParams();
  const double mu_red = p.mass1_kg * p.mass2_kg / (p.mass1_kg + p.mass2_kg);
  for (double approach : kGrazingApproaches_mps) {
    const Impact i = grazingImpact(approach);
    const auto r = resolveBallBallImpact(p, i.b1, i.b2, i.n);
    EXPECT_NEAR(r.normal_impulse_Ns / (mu_red * (1 + p.restitution) * approach), 1.0,
                kAlgebraicRelative)
        << approach;
    EXPECT_LE(kineticEnergy(p, r.ball1, r.ball2),
              kineticEnergy(p, i.b1, i.b2) * (1 + kEnergyRoundoffRelative))
        << approach;
  }
}

// ---------------------------------------------------------------------------------------------
// Accuracy of the Mathavan integration

TEST(BallBallImpact, MathavanAdaptiveSolutionIsConverged) {
  BallBallParams p = snookerMathavan2014Params();
  BallBallParams reference = p;
  reference.tolerance = 1e-14;
  for (const Impact& i : randomImpacts(31, 300)) {
    const auto r = resolveBallBallImpact(p, i.b1, i.b2, i.n);
    const auto best = resolveBallBallImpact(reference, i.b1, i.b2, i.n);
    EXPECT_LE(maxStateDifference(r, best, p.radius_m),
              kIntegratedRelative * speedScale(p, i.b1, i.b2));
  }
}

TEST(BallBallImpact, PaperEulerSchemeConvergesToTheAdaptiveSolution) {
  // An independent check of the adaptive solver: the paper's first-order scheme approaches it as
  // 1/N. Rolling cue ball with side spin, so every friction (ball, both cloths) is active.
  const BallBallParams p = snookerMathavan2014Params();
  const double R = p.radius_m;
  BallVelocity cue = rollingBall({1.5, 0, 0}, R);
  cue.w.z() = 30;
  const BallVelocity object = ballOf(Vector3d::Zero(), {0, 0, -10});
  const Vector3d n(std::cos(35 * kDeg), -std::sin(35 * kDeg), 0);
  const auto adaptive = resolveBallBallImpact(p, cue, object, n);
  std::vector<double> errors;
  for (int steps : {1000, 8000, 64000}) {
    BallBallParams euler = p;
    euler.fixed_steps = steps;
    errors.push_back(maxStateDifference(resolveBallBallImpact(euler, cue, object, n), adaptive, R));
  }
  // First order: 8x the steps gives about 8x less error; ask for at least 4x each time.
  EXPECT_LT(errors[1], errors[0] / 4);
  EXPECT_LT(errors[2], errors[1] / 4);
  EXPECT_LT(errors[2], 1e-4);  // m/s
}

// ---------------------------------------------------------------------------------------------
// Mathavan et al. (2014) data

struct SnookerShot {
  double speed_mps, topspin_radps, cut_deg;
  double measured_cue_mps, measured_object_mps;  // physics-notes section 3
  // Values quoted as the paper's Tables 1 and 2 in the pooltool project's test of its Mathavan
  // model (tests/physics/resolve/ball_ball/test_frictional_mathavan.py): rolled speeds and the
  // angles of both balls' rolled paths from the cue ball's incoming path. They differ from the
  // measured values, so they are the paper's simulated results (an inference; check the paper).
  double published_cue_mps, published_object_mps, published_cue_deg, published_object_deg;
};

// Model (this code) against measurement, speeds after both balls roll again, m/s:
//   V0     cut     cue: model / measured      object: model / measured
//   1.539  33.83        0.914 / 0.816 (!)             0.831 / 0.836
//   1.032  26.36        0.520 / 0.520                 0.599 / 0.629
//   1.364  40.52        0.917 / 0.925                 0.676 / 0.700
//   1.731  46.50        1.278 / 1.275                 0.779 / 0.787
//   0.942  18.05        0.384 / 0.365                 0.579 / 0.581
// Speeds straight after the impact (before the cloth works) are cue 0.827, 0.442, 0.857, 1.217,
// 0.283 and object 1.203, 0.870, 0.976, 1.123, 0.842: the object balls' measured speeds are about
// 5/7 of these, which shows the measurements were taken once the balls rolled.
// (!) The first shot's cue ball is 0.098 m/s slower than the model, and than the paper's own model
// (0.914); its object ball agrees, and no other value is off by more than 0.030 m/s.
const SnookerShot kShots[] = {
    {1.539, 58.63, 33.83, 0.816, 0.836, 0.914, 0.831, 31.93, 32.20},
    {1.032, 39.31, 26.36, 0.520, 0.629, 0.520, 0.599, 32.45, 25.07},
    {1.364, 51.96, 40.52, 0.925, 0.700, 0.917, 0.676, 29.91, 38.62},
    {1.731, 65.94, 46.50, 1.275, 0.787, 1.280, 0.780, 27.32, 44.38},
    {0.942, 35.89, 18.05, 0.365, 0.581, 0.383, 0.579, 29.47, 17.15},
};
// The one measured value the model misses by more than kMeasuredSpeedTolerance; kept visible with
// its own bound so that any change in the model's value shows up.
constexpr double kFirstShotCueDiscrepancy = 0.12;  // m/s

struct ShotOutcome {
  Vector3d cue_rolled, object_rolled;
};

ShotOutcome playShot(const SnookerShot& s) {
  const BallBallParams p = snookerMathavan2014Params();
  // Cue ball along +x rolling with the measured topspin; the object ball sits off to the right.
  const BallVelocity cue = ballOf({s.speed_mps, 0, 0}, {0, s.topspin_radps, 0});
  const Vector3d n(std::cos(s.cut_deg * kDeg), -std::sin(s.cut_deg * kDeg), 0);
  const auto r = resolveBallBallImpact(p, cue, BallVelocity{}, n);
  return {rolledVelocity(r.ball1, p.radius_m), rolledVelocity(r.ball2, p.radius_m)};
}

TEST(BallBallImpact, MathavanAgreesWithMeasuredSnookerShots) {
  for (std::size_t k = 0; k < std::size(kShots); ++k) {
    const SnookerShot& s = kShots[k];
    const ShotOutcome o = playShot(s);
    const double cue_bound = k == 0 ? kFirstShotCueDiscrepancy : kMeasuredSpeedTolerance;
    EXPECT_NEAR(o.cue_rolled.norm(), s.measured_cue_mps, cue_bound) << "shot " << k;
    EXPECT_NEAR(o.object_rolled.norm(), s.measured_object_mps, kMeasuredSpeedTolerance)
        << "shot " << k;
  }
}

TEST(BallBallImpact, MathavanReproducesThePublishedModelValues) {
  // Checks this reading of the paper's method (table reaction only from the vertical ball-ball
  // friction, on the ball it presses down) against the paper's own numbers.
  for (std::size_t k = 0; k < std::size(kShots); ++k) {
    const SnookerShot& s = kShots[k];
    const ShotOutcome o = playShot(s);
    EXPECT_NEAR(o.cue_rolled.norm(), s.published_cue_mps, kPublishedSpeedTolerance) << k;
    EXPECT_NEAR(o.object_rolled.norm(), s.published_object_mps, kPublishedSpeedTolerance) << k;
    const double cue_deg = std::atan2(-o.cue_rolled.y(), o.cue_rolled.x()) / kDeg;
    const double object_deg = std::atan2(-o.object_rolled.y(), o.object_rolled.x()) / kDeg;
    EXPECT_NEAR(std::abs(cue_deg), s.published_cue_deg, kPublishedAngleTolerance) << k;
    EXPECT_NEAR(object_deg, s.published_object_deg, kPublishedAngleTolerance) << k;
  }
}

// ---------------------------------------------------------------------------------------------
// Bad input

TEST(BallBallImpact, RejectsBadContacts) {
  const BallBallParams p = poolParams();
  const BallVelocity moving = ballOf({1, 0, 0}, Vector3d::Zero());
  const BallVelocity resting{};
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto resolve = [&](BallVelocity a, BallVelocity b, Vector3d n) {
    return [=] { resolveBallBallImpact(p, a, b, n); };
  };
  expectValueRejected(resolve(moving, resting, {1.1, 0, 0}), "line of centres |n|");
  expectValueRejected(resolve(moving, resting, {0.8, 0, 0.6}), "line of centres n_z");
  expectValueRejected(resolve(moving, resting, {nan, 0, 0}), "line of centres n_x");
  expectValueRejected(resolve(ballOf({nan, 0, 0}, Vector3d::Zero()), resting, Vector3d::UnitX()),
                      "ball 1 v_x");
  expectValueRejected(resolve(moving, ballOf(Vector3d::Zero(), {0, nan, 0}), Vector3d::UnitX()),
                      "ball 2 w_y");
  expectValueRejected(resolve(ballOf({1, 0, 0.1}, Vector3d::Zero()), resting, Vector3d::UnitX()),
                      "ball 1 v_z");
  // Regression (found by fuzzing): a speed of 1e306 m/s ran the Euler scheme out of increments
  // (std::logic_error); speeds and spins beyond the bounds of cushion_model.h are refused.
  expectValueRejected(resolve(moving, ballOf({0, -1e306, 0}, Vector3d::Zero()), Vector3d::UnitX()),
                      "ball 2 v_y");
  expectValueRejected(
      resolve(ballOf({1, 0, 0}, {0, 0, 2 * kMaxBallSpin_radps}), resting, Vector3d::UnitX()),
      "ball 1 w_z");
  // Separating, and grazing (no normal approach): the caller must not ask for an impact.
  expectValueRejected(resolve(moving, resting, -Vector3d::UnitX()), "approach speed");
  expectValueRejected(resolve(moving, resting, Vector3d::UnitY()), "approach speed");
  expectValueRejected(resolve(resting, resting, Vector3d::UnitX()), "approach speed");
  // Regression (found by fuzzing): an approach of 1e-311 m/s (subnormal) stalled the Mathavan
  // integration; approaches below kMinApproachSpeed_mps are refused.
  expectValueRejected(resolve(ballOf({1e-311, 0, 0}, Vector3d::Zero()), resting, Vector3d::UnitX()),
                      "approach speed");
}

TEST(BallBallImpact, RejectsBadParameters) {
  const BallVelocity moving = ballOf({1, 0, 0}, Vector3d::Zero());
  auto with = [&](const std::function<void(BallBallParams&)>& change, BallBallParams p) {
    change(p);
    return [=] { resolveBallBallImpact(p, moving, BallVelocity{}, Vector3d::UnitX()); };
  };
  const BallBallParams pool = poolParams(), snooker = snookerMathavan2014Params();
  expectValueRejected(with([](auto& p) { p.mass1_kg = -0.1; }, pool), "ball 1 mass (kg)");
  expectValueRejected(with([](auto& p) { p.radius_m = 0; }, pool), "ball radius (m)");
  // Regression (found by fuzzing): radii hundreds of orders of magnitude from a ball's made the
  // Mathavan integration exhaust its step budget (std::logic_error); they are refused up front.
  expectValueRejected(with([](auto& p) { p.radius_m = 1e-200; }, snooker), "ball radius (m)");
  expectValueRejected(with([](auto& p) { p.radius_m = 1e300; }, snooker), "ball radius (m)");
  // Likewise subnormal masses (1e-309 kg).
  expectValueRejected(with([](auto& p) { p.mass1_kg = p.mass2_kg = 1e-309; }, snooker),
                      "ball 1 mass (kg)");
  expectValueRejected(with([](auto& p) { p.mass2_kg = 1e9; }, pool), "ball 2 mass (kg)");
  expectValueRejected(with([](auto& p) { p.restitution = 1.2; }, pool), "ball-ball restitution e");
  expectValueRejected(with([](auto& p) { p.restitution = std::nan(""); }, snooker),
                      "ball-ball restitution e");
  expectValueRejected(with([](auto& p) { p.friction_fit_b = 1.0; }, pool), "friction fit a + b");
  expectValueRejected(with(
                          [](auto& p) {
                            p.friction_law = BallBallFrictionLaw::Constant;
                            p.constant_friction = -0.1;
                          },
                          pool),
                      "ball-ball friction mu");
  expectValueRejected(with([](auto& p) { p.ball_friction = 0.4; }, snooker),
                      "ball-ball friction mu_b");
  expectValueRejected(with([](auto& p) { p.cloth_friction = 1.0; }, snooker),
                      "cloth friction mu_s");
  expectValueRejected(with([](auto& p) { p.tolerance = 0; }, snooker), "integration tolerance");
  expectValueRejected(with([](auto& p) { p.fixed_steps = -5; }, snooker), "fixed Euler steps");
}

}  // namespace
}  // namespace baize::physics
