// Tests of the shared cushion model pieces: the incoming state, the slip velocities at the two
// contacts, the impulse response (eq. 14a and its partners, derived again here from Newton-Euler),
// kinetic energy and the validation of parameters and incoming states.
#include "physics/cushion_model.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "physics/cushion_exact_solver.h"
#include "physics/value_text.h"
#include "tests/physics/cushion_test_support.h"
#include "tests/physics/rejection_test_support.h"

namespace baize::physics {
namespace {

using test::degrees;
using test::expectRejected;
using test::RandomImpacts;
using ::testing::HasSubstr;

// Closed forms evaluated in a different order than the code: a few units in the last place, scaled
// by the size of the largest term (dimensionless, relative).
constexpr double kRoundoffRelative = 1e-13;
constexpr std::uint64_t kSeed = 0x5eed'c0ffee'0001ULL;
constexpr int kRandomCases = 200;  // cheap closed-form checks: enough to cover every sign pattern

Eigen::Vector3d randomVector(RandomImpacts& random, double scale) {
  return {random.uniform(-scale, scale), random.uniform(-scale, scale),
          random.uniform(-scale, scale)};
}

// The tangent basis at the cushion contact I and the contact positions, written from the geometry:
// the nose touches the ball at angle theta above its equator, on the +y side.
struct ContactGeometry {
  double s, c;
  Eigen::Vector3d r_I, r_C, normal_into_cushion, x_axis, y_prime;
  explicit ContactGeometry(const CushionParams& p) {
    s = (p.contact_height_m - p.radius_m) / p.radius_m;
    c = std::sqrt(1 - s * s);
    r_I = p.radius_m * Eigen::Vector3d(0, c, s);
    r_C = Eigen::Vector3d(0, 0, -p.radius_m);
    normal_into_cushion = Eigen::Vector3d(0, c, s);
    x_axis = Eigen::Vector3d::UnitX();
    y_prime = Eigen::Vector3d(0, -s, c);  // in the y-z plane, perpendicular to the normal, upward
  }
};

TEST(CushionModel, ContactSinThetaIsTheNoseHeightAboveTheEquatorOverTheRadius) {
  CushionParams p;  // h = 7R/5: the paper's sin(theta) = 2/5
  EXPECT_NEAR(contactSinTheta(p), 0.4, kRoundoffRelative);
  p.radius_m = 0.028575;  // pool ball, nose at 63.5 % of the diameter
  p.contact_height_m = 0.635 * 2 * p.radius_m;
  EXPECT_NEAR(contactSinTheta(p), 0.27, kRoundoffRelative);
}

TEST(CushionModel, IncomingBallFollowsThePhysicsNotesAssignment) {
  RandomImpacts random(kSeed);
  for (int i = 0; i < kRandomCases; ++i) {
    const double V0 = random.uniform(0.1, 3.0);
    const double a = degrees(random.uniform(1, 179));
    const double wT = random.uniform(-100, 100);
    const double wS = random.uniform(-100, 100);
    const BallVelocity ball = incomingBall(V0, a, wT, wS);
    EXPECT_DOUBLE_EQ(ball.v.x(), V0 * std::cos(a));
    EXPECT_DOUBLE_EQ(ball.v.y(), V0 * std::sin(a));
    EXPECT_EQ(ball.v.z(), 0.0);
    EXPECT_DOUBLE_EQ(ball.w.x(), -wT * std::sin(a));
    EXPECT_DOUBLE_EQ(ball.w.y(), wT * std::cos(a));
    EXPECT_DOUBLE_EQ(ball.w.z(), wS);
    // Topspin is about the horizontal axis perpendicular to the velocity; sidespin is about z.
    EXPECT_NEAR(ball.w.head<2>().dot(ball.v.head<2>()), 0.0, kRoundoffRelative * V0 * 100);
    EXPECT_NEAR(ball.w.head<2>().norm(), std::abs(wT), kRoundoffRelative * 100);
  }
}

TEST(CushionModel, NaturalRollHasNoClothSlipAndHeadOnMeansAlphaNinetyDegrees) {
  const CushionParams p;
  const double R = p.radius_m;
  for (double alpha_deg = 1; alpha_deg < 180; alpha_deg += 7) {
    for (double V0 : {0.1, 1.0, 2.5}) {
      const BallVelocity ball = incomingBall(V0, degrees(alpha_deg), V0 / R, 0.7 * V0 / R);
      EXPECT_LT(clothSlip(p, ball).norm(), kRoundoffRelative * V0) << "alpha " << alpha_deg;
      // Rolling: the cloth contact point is at rest, v + w x r_C = 0 (sidespin does not matter).
      const Eigen::Vector3d contact_velocity = ball.v + ball.w.cross(Eigen::Vector3d(0, 0, -R));
      EXPECT_LT(contact_velocity.norm(), kRoundoffRelative * V0);
    }
  }
  const BallVelocity head_on = incomingBall(1.0, degrees(90), 0, 0);
  EXPECT_NEAR(head_on.v.x(), 0.0, kRoundoffRelative);
  EXPECT_DOUBLE_EQ(head_on.v.y(), 1.0);
}

// Slip = velocity of the ball's material point at the contact, v + w x r, resolved on the contact's
// tangent basis. Computed here from the vectors, not from the notes' component formulas.
TEST(CushionModel, SlipVelocitiesAreTheContactPointVelocitiesInTheTangentBases) {
  RandomImpacts random(kSeed + 1);
  for (int i = 0; i < kRandomCases; ++i) {
    const CushionParams p = random.randomParams();
    const ContactGeometry g(p);
    BallVelocity ball;
    ball.v = randomVector(random, 3.0);  // v_z != 0 too: the formula keeps the v_z cos(theta) term
    ball.w = randomVector(random, 3.0 / p.radius_m);
    const Eigen::Vector3d at_I = ball.v + ball.w.cross(g.r_I);
    const Eigen::Vector3d at_C = ball.v + ball.w.cross(g.r_C);
    const double scale = 10.0;  // m/s, bounds |v| + R |w| here
    const Eigen::Vector2d cushion = cushionSlip(p, ball);
    EXPECT_NEAR(cushion.x(), at_I.dot(g.x_axis), kRoundoffRelative * scale);
    EXPECT_NEAR(cushion.y(), at_I.dot(g.y_prime), kRoundoffRelative * scale);
    // The contact point does not move along the normal through a velocity of rotation.
    EXPECT_NEAR(at_I.dot(g.normal_into_cushion), g.c * ball.v.y() + g.s * ball.v.z(),
                kRoundoffRelative * scale);
    const Eigen::Vector2d cloth = clothSlip(p, ball);
    EXPECT_NEAR(cloth.x(), at_C.x(), kRoundoffRelative * scale);
    EXPECT_NEAR(cloth.y(), at_C.y(), kRoundoffRelative * scale);
    // The notes' formulas (eq. 12a, 12b, 13a, 13b) agree with the vector form.
    const double R = p.radius_m;
    EXPECT_NEAR(cushion.x(), ball.v.x() + R * (ball.w.y() * g.s - ball.w.z() * g.c),
                kRoundoffRelative * scale);
    EXPECT_NEAR(cushion.y(), -ball.v.y() * g.s + ball.v.z() * g.c + R * ball.w.x(),
                kRoundoffRelative * scale);
    EXPECT_NEAR(cloth.x(), ball.v.x() - R * ball.w.y(), kRoundoffRelative * scale);
    EXPECT_NEAR(cloth.y(), ball.v.y() + R * ball.w.x(), kRoundoffRelative * scale);
  }
}

// Newton-Euler for the impulses of one increment, from the geometry: normal impulse P at I along
// -n, friction -a at I on (x, Y'), friction -b at C on (x, y), and a table normal impulse P_C at C
// chosen so that the net vertical impulse is zero (the ball stays on the table). Returns the
// velocity change and P_C.
struct NewtonEulerResponse {
  BallVelocity change;
  double table_normal_impulse_Ns;
};
NewtonEulerResponse newtonEuler(const CushionParams& p, double P, const Eigen::Vector2d& a,
                                const Eigen::Vector2d& b) {
  const ContactGeometry g(p);
  const Eigen::Vector3d at_I = -P * g.normal_into_cushion - a.x() * g.x_axis - a.y() * g.y_prime;
  const double table_normal = -at_I.z();
  const Eigen::Vector3d at_C(-b.x(), -b.y(), table_normal);
  const double inertia = 0.4 * p.mass_kg * p.radius_m * p.radius_m;
  NewtonEulerResponse out;
  out.change.v = (at_I + at_C) / p.mass_kg;
  out.change.w = (g.r_I.cross(at_I) + g.r_C.cross(at_C)) / inertia;
  out.table_normal_impulse_Ns = table_normal;
  return out;
}

TEST(CushionModel, ImpulseResponseIsNewtonEulerWithZeroNetVerticalImpulse) {
  RandomImpacts random(kSeed + 2);
  for (int i = 0; i < kRandomCases; ++i) {
    const CushionParams p = random.randomParams();
    const ContactGeometry g(p);
    const double P = random.uniform(0, 0.5);
    const Eigen::Vector2d a(random.uniform(-0.2, 0.2), random.uniform(-0.2, 0.2));
    const Eigen::Vector2d b(random.uniform(-0.2, 0.2), random.uniform(-0.2, 0.2));
    const BallVelocity got = impulseResponse(p, P, a, b);
    const NewtonEulerResponse expected = newtonEuler(p, P, a, b);
    const double speed_scale = 1.0 / p.mass_kg;  // m/s per N s of impulse
    EXPECT_EQ(got.v.z(), 0.0) << "the table holds the ball: no vertical velocity change";
    EXPECT_LT(test::velocityDifference(got, expected.change, p.radius_m),
              kRoundoffRelative * speed_scale);
    // Eq. 3d: P_C = P sin(theta) - dP_y'^I cos(theta), with the friction impulse dP_y'^I = -a_y.
    EXPECT_NEAR(expected.table_normal_impulse_Ns, P * g.s + a.y() * g.c, kRoundoffRelative);
    // Eqs. 3a, 3b and the angular impulse equations 4a-4c as printed in the paper, with
    // dP_x^I = -a_x, dP_y'^I = -a_y, dP_x^C = -b_x, dP_y^C = -b_y.
    const double M = p.mass_kg, R = p.radius_m;
    EXPECT_NEAR(M * got.v.x(), -a.x() - b.x(), kRoundoffRelative);
    EXPECT_NEAR(M * got.v.y(), -P * g.c + a.y() * g.s - b.y(), kRoundoffRelative);
    EXPECT_NEAR(2 * M * R / 5 * got.w.x(), -a.y() - b.y(), kRoundoffRelative);
    EXPECT_NEAR(2 * M * R / 5 * got.w.y(), -a.x() * g.s + b.x(), kRoundoffRelative);
    EXPECT_NEAR(2 * M * R / 5 * got.w.z(), a.x() * g.c, kRoundoffRelative);
  }
}

// With Coulomb friction at both contacts the response per unit normal impulse is eq. 14a and its
// five partners (physics-notes section 1).
TEST(CushionModel, ImpulseResponseGivesEquation14aAndItsPartnersForSlidingContacts) {
  RandomImpacts random(kSeed + 3);
  for (int i = 0; i < kRandomCases; ++i) {
    const CushionParams p = random.randomParams();
    const ContactGeometry g(p);
    const double phi = random.uniform(-test::kPi, test::kPi);        // slip direction at I
    const double phi_cloth = random.uniform(-test::kPi, test::kPi);  // slip direction at C
    const double mu_w = p.cushion_friction, mu_s = p.cloth_friction;
    const double q = g.s + mu_w * std::sin(phi) * g.c;  // dP_C/dP, eq. 8
    EXPECT_GT(q, 0) << "mu_w < tan(theta) keeps the table pressing on the ball";
    const BallVelocity rate =
        impulseResponse(p, 1.0, mu_w * Eigen::Vector2d(std::cos(phi), std::sin(phi)),
                        mu_s * q * Eigen::Vector2d(std::cos(phi_cloth), std::sin(phi_cloth)));
    const double M = p.mass_kg, k = 5 / (2 * M * p.radius_m);
    const double tol = kRoundoffRelative * k;
    EXPECT_NEAR(rate.v.x(), -(mu_w * std::cos(phi) + mu_s * std::cos(phi_cloth) * q) / M, tol);
    EXPECT_NEAR(rate.v.y(),
                -(g.c - mu_w * g.s * std::sin(phi) + mu_s * std::sin(phi_cloth) * q) / M, tol);
    EXPECT_EQ(rate.v.z(), 0.0);
    EXPECT_NEAR(rate.w.x(), -k * (mu_w * std::sin(phi) + mu_s * std::sin(phi_cloth) * q), tol);
    EXPECT_NEAR(rate.w.y(), -k * (mu_w * std::cos(phi) * g.s - mu_s * std::cos(phi_cloth) * q),
                tol);
    EXPECT_NEAR(rate.w.z(), k * mu_w * std::cos(phi) * g.c, tol);
  }
}

TEST(CushionModel, ImpulseResponseIsLinearInAllThreeImpulses) {
  RandomImpacts random(kSeed + 4);
  for (int i = 0; i < kRandomCases; ++i) {
    const CushionParams p = random.randomParams();
    auto draw = [&] {
      return Eigen::Vector2d(random.uniform(-0.2, 0.2), random.uniform(-0.2, 0.2));
    };
    const double P1 = random.uniform(0, 0.5), P2 = random.uniform(0, 0.5);
    const Eigen::Vector2d a1 = draw(), a2 = draw(), b1 = draw(), b2 = draw();
    const double lambda = random.uniform(-3, 3), mu = random.uniform(-3, 3);
    const BallVelocity one = impulseResponse(p, P1, a1, b1);
    const BallVelocity two = impulseResponse(p, P2, a2, b2);
    const BallVelocity combined =
        impulseResponse(p, lambda * P1 + mu * P2, lambda * a1 + mu * a2, lambda * b1 + mu * b2);
    BallVelocity expected;
    expected.v = lambda * one.v + mu * two.v;
    expected.w = lambda * one.w + mu * two.w;
    EXPECT_LT(test::velocityDifference(combined, expected, p.radius_m),
              kRoundoffRelative * 10 / p.mass_kg);
    const BallVelocity nothing =
        impulseResponse(p, 0, Eigen::Vector2d::Zero(), Eigen::Vector2d::Zero());
    EXPECT_EQ(nothing.v.norm() + nothing.w.norm(), 0.0);
  }
}

TEST(CushionModel, KineticEnergyIsTranslationPlusRotationOfASolidSphere) {
  CushionParams p;
  p.mass_kg = 0.25;
  p.radius_m = 0.5;
  BallVelocity ball;
  ball.v = {1, 2, 2};  // |v|^2 = 9
  ball.w = {0, 3, 4};  // |w|^2 = 25, I = 2/5 * 0.25 * 0.25 = 0.025 kg m^2
  EXPECT_NEAR(kineticEnergy(p, ball), 0.5 * 0.25 * 9 + 0.5 * 0.025 * 25, kRoundoffRelative);
  // Natural roll carries 7/5 of the translational energy.
  const CushionParams snooker;
  const BallVelocity rolling = incomingBall(2.0, degrees(30), 2.0 / snooker.radius_m, 0);
  EXPECT_NEAR(kineticEnergy(snooker, rolling), 1.4 * 0.5 * snooker.mass_kg * 4.0,
              kRoundoffRelative);
}

// The guard the random-impact tests put around physics calls must really trap, and only while it
// is alive: otherwise a NaN-producing path would pass those tests silently.
TEST(FloatingPointTrapsDeathTest, DivisionByZeroCrashesOnlyInsideTheGuard) {
  volatile double zero = 0;
  EXPECT_DEATH(
      {
        test::FloatingPointTraps traps;
        volatile double infinite = 1.0 / zero;
        (void)infinite;
      },
      "");
  EXPECT_DEATH(
      {
        test::FloatingPointTraps traps;
        volatile double invalid = zero / zero;
        (void)invalid;
      },
      "");
  { test::FloatingPointTraps traps; }
  volatile double infinite = 1.0 / zero;  // no trap after the guard is gone
  EXPECT_TRUE(std::isinf(infinite));
}

// --- validation -------------------------------------------------------------------------------

// A radius that is exact in binary (1/32 m), so the limits R and 2R print exactly.
CushionParams exactParams() {
  CushionParams p;
  p.radius_m = 0.03125;
  p.contact_height_m = 0.04375;  // 1.4 R
  return p;
}

TEST(CushionModelValidation, AcceptsTheDefaultsAndPoolGeometry) {
  EXPECT_NO_THROW(validateCushionParams(CushionParams{}));
  CushionParams pool;
  pool.radius_m = 0.028575;
  pool.contact_height_m = 1.27 * pool.radius_m;
  pool.cushion_friction = 0.2;  // below tan(theta) = 0.28 for this nose
  EXPECT_NO_THROW(validateCushionParams(pool));
  EXPECT_NO_THROW(validateCushionParams(exactParams()));
  CushionParams elastic_frictionless = exactParams();
  elastic_frictionless.restitution = 1.0;  // the closed end of [1e-6, 1]
  elastic_frictionless.cushion_friction = 0;
  elastic_frictionless.cloth_friction = 0;
  EXPECT_NO_THROW(validateCushionParams(elastic_frictionless));
}

TEST(CushionModelValidation, RejectsNonPhysicalMassRadiusAndContactHeight) {
  auto with = [](auto change) {
    CushionParams p = exactParams();
    change(p);
    return [p] { validateCushionParams(p); };
  };
  expectRejected(with([](CushionParams& p) { p.mass_kg = -0.5; }),
                 {"mass", "-0.5", "[0.001, 1000]"});
  expectRejected(with([](CushionParams& p) { p.mass_kg = 0; }), {"mass", "= 0 "});
  expectRejected(with([](CushionParams& p) { p.radius_m = -0.25; }), {"radius", "-0.25"});
  expectRejected(with([](CushionParams& p) { p.radius_m = 0; }), {"radius", "= 0 "});
  // Regression (found by fuzzing): a radius of 1e300 m made the exact solver exhaust its step
  // budget (std::logic_error); radii outside [1 mm, 1 m] are refused with the range.
  expectRejected(with([](CushionParams& p) { p.radius_m = 1e300; }), {"radius", "1e+300", "1]"});
  expectRejected(with([](CushionParams& p) { p.radius_m = 1e-200; }), {"radius", "0.001"});
  // h must lie in (R, R (1 + sin 80 deg)] = (0.03125, 0.06202...]: the nose below the ball's top.
  expectRejected(with([](CushionParams& p) { p.contact_height_m = 0.03125; }),
                 {"contact height", "0.03125", "sin 80 deg) = 0.06202"});
  // Regression (found by fuzzing): at h = 1.99999 R the paper scheme exhausted its increments.
  expectRejected(with([](CushionParams& p) { p.contact_height_m = 1.99999 * 0.03125; }),
                 {"contact height", "0.0624996"});
  expectRejected(with([](CushionParams& p) { p.contact_height_m = 0.0621; }),
                 {"contact height", "0.0621"});
  expectRejected(with([](CushionParams& p) { p.contact_height_m = 0.0625; }),
                 {"contact height", "= 0.0625"});
  expectRejected(with([](CushionParams& p) { p.contact_height_m = 0.015625; }),
                 {"contact height", "0.015625"});
  expectRejected(with([](CushionParams& p) { p.contact_height_m = 0.078125; }),
                 {"contact height", "0.078125"});
}

TEST(CushionModelValidation, RejectsRestitutionOutsideItsRange) {
  for (double e : {0.0, 1.5, -0.25, 1.0000000000000002, 5e-8, std::nextafter(kMinRestitution, 0)}) {
    CushionParams p = exactParams();
    p.restitution = e;
    expectRejected([p] { validateCushionParams(p); },
                   {"e_e = " + valueText(e) + " ", "[1e-06, 1]"});
  }
  CushionParams least = exactParams();
  least.restitution = kMinRestitution;
  EXPECT_NO_THROW(validateCushionParams(least));
}

TEST(CushionModelValidation, RejectsCushionFrictionAtOrAboveTanTheta) {
  CushionParams p = exactParams();  // sin(theta) = 0.4, tan(theta) = 0.436...
  p.cushion_friction = 0.4375;
  expectRejected([p] { validateCushionParams(p); }, {"mu_w = 0.4375", "tan(theta)"});
  p.cushion_friction = -0.125;
  expectRejected([p] { validateCushionParams(p); }, {"mu_w = -0.125"});
  p.cushion_friction = 0.4;  // just below tan(theta): allowed
  EXPECT_NO_THROW(validateCushionParams(p));
}

TEST(CushionModelValidation, RejectsClothFrictionThatCouldHoldTheBallAgainstTheCushion) {
  CushionParams p = exactParams();
  p.cloth_friction = 1.0;
  expectRejected([p] { validateCushionParams(p); }, {"mu_s = 1 "});
  p.cloth_friction = -0.5;
  expectRejected([p] { validateCushionParams(p); }, {"mu_s = -0.5"});
  // cos th - mu_w sin th - mu_s (sin th + mu_w cos th) < 0: the normal velocity could stop falling.
  p.cushion_friction = 0.43;
  p.cloth_friction = 0.99;
  const double s = 0.4, c = std::sqrt(1 - s * s);
  ASSERT_LT(c - 0.43 * s - 0.99 * (s + 0.43 * c), 0);
  expectRejected([p] { validateCushionParams(p); }, {"mu_s = 0.99 ", "mu_w"});
}

// Regression (found by fuzzing): within 1e-6 of that bound friction nearly holds the ball, the
// rebound needs an impulse that grows without bound and the exact solver ran out of steps. A margin
// of kMinNormalRateShare of cos theta is required; just inside it the impact solves.
TEST(CushionModelValidation, RejectsFrictionThatCouldNearlyHoldTheBallAgainstTheCushion) {
  CushionParams p;
  p.mass_kg = 0.19967217720106065;
  p.radius_m = 0.017411764705882352;
  p.contact_height_m = 0.031341176470588233;  // sin theta = 0.8
  p.restitution = 0.8;
  p.cushion_friction = 1.0 / 3;
  const double s = contactSinTheta(p), c = std::sqrt(1 - s * s);
  auto clothFrictionAtShare = [&](double share) {  // the margin as a share of cos theta
    return (c * (1 - share) - p.cushion_friction * s) / (s + p.cushion_friction * c);
  };
  BallVelocity in;  // the fuzzer's ball: fast sidespin and topspin
  in.v = {0.92156862745098045, 2.9607843591274658, 0};
  in.w = {30.718954248366018, 30.719333219043747, 166.66666666666669};
  p.cloth_friction = 0.33333276487731672;  // the fuzzer's: a margin of about 1e-6 cos theta
  ASSERT_LT(c - p.cushion_friction * s - p.cloth_friction * (s + p.cushion_friction * c),
            kMinNormalRateShare * c);
  expectRejected([p] { validateCushionParams(p); }, {"mu_s = 0.3333327648773167 ", "mu_w"});
  expectRejected([p, in] { solveCushionImpactExact(p, in); }, {"mu_s"});
  p.cloth_friction = clothFrictionAtShare(0.5 * kMinNormalRateShare);
  EXPECT_THROW(validateCushionParams(p), std::invalid_argument);
  p.cloth_friction = clothFrictionAtShare(1.001 * kMinNormalRateShare);
  EXPECT_NO_THROW(validateCushionParams(p));
  const CushionImpactResult r = solveCushionImpactExact(p, in);
  EXPECT_LT(r.after.v.y(), 0);
  EXPECT_LE(kineticEnergy(p, r.after), kineticEnergy(p, in));
}

TEST(CushionModelValidation, RejectsNonFiniteParameters) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  struct Field {
    double CushionParams::*member;
    const char* name;
  };
  const Field fields[] = {{&CushionParams::mass_kg, "mass"},
                          {&CushionParams::radius_m, "radius"},
                          {&CushionParams::contact_height_m, "contact height"},
                          {&CushionParams::restitution, "e_e"},
                          {&CushionParams::cushion_friction, "mu_w"},
                          {&CushionParams::cloth_friction, "mu_s"}};
  for (const Field& field : fields) {
    for (double bad : {nan, inf, -inf}) {
      CushionParams p = exactParams();
      p.*(field.member) = bad;
      const std::string shown = std::isnan(bad) ? "nan" : (bad > 0 ? "= inf" : "= -inf");
      SCOPED_TRACE(std::string(field.name) + " " + shown);
      expectRejected([p] { validateCushionParams(p); }, {field.name, shown, "finite"});
    }
  }
}

TEST(CushionModelValidation, RejectsBallsNotMovingIntoTheCushion) {
  EXPECT_NO_THROW(validateIncomingBall(incomingBall(1.0, degrees(1), 0, 0)));
  EXPECT_NO_THROW(validateIncomingBall(incomingBall(1.0, degrees(179), 0, 0)));
  // alpha = 0: sliding along the cushion, v_y = 0 exactly.
  expectRejected([] { validateIncomingBall(incomingBall(1.0, 0.0, 0, 0)); }, {"v_y", "= 0 "});
  BallVelocity away;
  away.v = {0.5, -0.25, 0};
  expectRejected([away] { validateIncomingBall(away); }, {"v_y", "-0.25", "v_y > 0"});
  BallVelocity airborne;
  airborne.v = {0.5, 0.5, 0.125};
  expectRejected([airborne] { validateIncomingBall(airborne); }, {"v_z", "0.125"});
}

TEST(CushionModelValidation, RejectsNonFiniteIncomingComponents) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const char* names[] = {"v_x", "v_y", "v_z", "w_x", "w_y", "w_z"};
  for (int i = 0; i < 6; ++i) {
    for (double bad : {nan, inf, -inf}) {
      BallVelocity ball = incomingBall(1.0, degrees(60), 10, 5);
      (i < 3 ? ball.v[i] : ball.w[i - 3]) = bad;
      const std::string shown = std::isnan(bad) ? "nan" : (bad > 0 ? "= inf" : "= -inf");
      SCOPED_TRACE(std::string(names[i]) + " " + shown);
      expectRejected([ball] { validateIncomingBall(ball); }, {names[i], shown});
    }
  }
}

// Regression (found by fuzzing): an incoming v_y of 1.8e308 m/s overflowed the exact solver's
// scales and exhausted its step budget (std::logic_error). Speeds and spins beyond the bounds are
// refused with the bound; the bounds themselves are accepted.
TEST(CushionModelValidation, RejectsSpeedsAndSpinsBeyondTheBounds) {
  BallVelocity ball = incomingBall(1.0, degrees(60), 10, 5);
  ball.v.y() = kMaxBallSpeed_mps;
  ball.w.z() = -kMaxBallSpin_radps;
  EXPECT_NO_THROW(validateIncomingBall(ball));
  BallVelocity fast = ball;
  fast.v.y() = std::numeric_limits<double>::max();
  expectRejected([fast] { validateIncomingBall(fast); }, {"v_y", "at most 1000"});
  BallVelocity spinning = ball;
  spinning.w.x() = 2 * kMaxBallSpin_radps;
  expectRejected([spinning] { validateIncomingBall(spinning); }, {"w_x", "2e+06", "at most 1e+06"});
  // Regression (found by fuzzing): v_y = 5e-324 m/s stalled the exact solver (zero first step).
  BallVelocity creeping = ball;
  creeping.v.y() = std::numeric_limits<double>::denorm_min();
  expectRejected([creeping] { validateIncomingBall(creeping); }, {"v_y", "at least 1e-100"});
}

}  // namespace
}  // namespace baize::physics
