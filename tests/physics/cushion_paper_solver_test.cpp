// Tests of the paper's Euler scheme (section 3.4): its closed-form frictionless result, energy,
// mirror symmetry, linear scaling, the Coulomb law in every increment, first-order convergence to
// the exact solver, the publication's head-on rolling rebound and the rejection of bad options.
#include "physics/cushion_paper_solver.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "physics/cushion_exact_solver.h"
#include "tests/physics/cushion_test_support.h"
#include "tests/physics/rejection_test_support.h"

namespace baize::physics {
namespace {

using test::degrees;
using test::expectRejected;
using test::FloatingPointTraps;
using test::RandomImpacts;
using test::velocityDifference;
using ::testing::HasSubstr;

constexpr std::uint64_t kSeed = 0x5eed'0000'ba12'0002ULL;
// Random impacts per property: each takes about 0.1 ms at N = 2000, so a second of CPU covers many.
constexpr int kRandomImpacts = 1000;
constexpr int kRandomSteps = 2000;  // N for the random-impact properties

// Arithmetic in a different association than the solver: relative to the value's scale.
constexpr double kRoundoffRelative = 1e-12;
// Energy may rise by at most this many M v_y0^2 / N (J): the restitution stop rule overshoots the
// target work by at most one step, M dv |v_y'| <= c (1 + e) M v_y0^2 / N <= 2 M v_y0^2 / N, and the
// second-order terms of the Euler steps add M |dv|^2 / 2 per step, a further O(1/N) below 2
// (measured at most 0.6 over random impacts).
constexpr double kPaperEnergySlack = 4.0;
// Recovering the per-increment friction impulses from a trace divides velocity differences of
// about V0 / N by dP: relative error about N times the roundoff of the velocities.
constexpr double kRecoveredFrictionRelative = 1e-8;

CushionImpactResult solvePaper(const CushionParams& params, const BallVelocity& incoming, int steps,
                               bool record_trace = false) {
  PaperSolverOptions options;
  options.steps = steps;
  options.record_trace = record_trace;
  FloatingPointTraps traps;  // a NaN or infinity on any path crashes the test
  return solveCushionImpactPaper(params, incoming, options);
}

void expectIdentical(const BallVelocity& a, const BallVelocity& b) {
  for (int k = 0; k < 3; ++k) {
    EXPECT_EQ(a.v[k], b.v[k]);
    EXPECT_EQ(a.w[k], b.w[k]);
  }
}

// --- 1. frictionless limit -----------------------------------------------------------------------

// Without friction only v_y changes, at the constant rate -cos(theta)/M. Exactly, compression ends
// at P_c = M v_y0 / c with W_c = M v_y0^2 / 2, and the energetic restitution gives v_y' = -e v_y0.
// The scheme stops at the first step past each target, and the trapezoidal work is exact for v_y
// linear in P, so with dv = c dP / M = c (1 + e) v_y0 / N:
//   P_c in [M v_y0 / c, M v_y0 / c + dP),  W_c in (M v_y0^2 / 2 - M dv^2 / 2, M v_y0^2 / 2],
//   0 <= |v_y'| - e v_y0 <= dv (1 + dv / (e v_y0)),
// every other component unchanged bit for bit (friction adds exact zeros).
TEST(CushionPaperSolver, FrictionlessLimitIsExactUpToOneStepOfTheStopRules) {
  RandomImpacts random(kSeed);
  for (int i = 0; i < 100; ++i) {
    test::RandomImpact impact = random.next(true);
    impact.params.cushion_friction = 0;
    impact.params.cloth_friction = 0;
    const CushionParams& p = impact.params;
    const double e = p.restitution, M = p.mass_kg;
    const double s = contactSinTheta(p), c = std::sqrt(1 - s * s);
    const double vy0 = impact.incoming.v.y();
    for (int steps : {1000, 16000}) {
      SCOPED_TRACE("impact " + std::to_string(i) + ", N = " + std::to_string(steps));
      const CushionImpactResult result = solvePaper(p, impact.incoming, steps);
      const double dP = (1 + e) * M * vy0 / steps;
      const double dv = c * dP / M;
      const double roundoff = kRoundoffRelative * vy0;
      const double excess = -result.after.v.y() - e * vy0;
      EXPECT_GE(excess, -roundoff);
      EXPECT_LE(excess, dv * (1 + dv / (e * vy0)) + roundoff);
      EXPECT_EQ(result.after.v.x(), impact.incoming.v.x());
      EXPECT_EQ(result.after.v.z(), 0.0);
      for (int k = 0; k < 3; ++k) EXPECT_EQ(result.after.w[k], impact.incoming.w[k]);
      const double exact_Pc = M * vy0 / c;
      EXPECT_GE(result.compression_impulse_Ns, exact_Pc * (1 - kRoundoffRelative));
      EXPECT_LT(result.compression_impulse_Ns, exact_Pc + dP * (1 + kRoundoffRelative));
      const double exact_Wc = M * vy0 * vy0 / 2;
      EXPECT_LE(result.compression_work_J, exact_Wc * (1 + kRoundoffRelative));
      EXPECT_GT(result.compression_work_J,
                exact_Wc - M * dv * dv / 2 - exact_Wc * kRoundoffRelative);
      EXPECT_GT(result.final_impulse_Ns, result.compression_impulse_Ns);
    }
  }
}

// --- 2. energy
// -------------------------------------------------------------------------------------

// The normal force at I does net work -(1 - e^2) W_c, friction only dissipates and the table's
// normal force does no work (its contact point has no vertical velocity), so exactly
// T' <= T - (1 - e^2) W_c. The scheme keeps that up to its first-order error (kPaperEnergySlack).
TEST(CushionPaperSolver, KineticEnergyNeverGrowsBeyondTheSchemesFirstOrderError) {
  RandomImpacts random(kSeed + 1);
  for (int i = 0; i < kRandomImpacts; ++i) {
    const test::RandomImpact impact = random.next(true);
    const CushionParams& p = impact.params;
    const CushionImpactResult result = solvePaper(p, impact.incoming, kRandomSteps);
    const double before = kineticEnergy(p, impact.incoming);
    const double after = kineticEnergy(p, result.after);
    const double vy0 = impact.incoming.v.y();
    const double slack = kPaperEnergySlack * p.mass_kg * vy0 * vy0 / kRandomSteps;
    const double e = p.restitution;
    EXPECT_LE(after, before - (1 - e * e) * result.compression_work_J + slack) << "impact " << i;
    EXPECT_GT(result.compression_work_J, 0) << "impact " << i;
    EXPECT_LT(result.compression_impulse_Ns, result.final_impulse_Ns) << "impact " << i;
    EXPECT_LT(result.after.v.y(), 0) << "the ball leaves the cushion, impact " << i;
  }
}

// --- 3. mirror symmetry
// ----------------------------------------------------------------------------

// The reflection x -> -x maps a solution onto a solution: v -> (-vx, vy, vz), w -> (wx, -wy, -wz).
// For the incoming ball that is alpha -> pi - alpha with the sidespin reversed. Every operation of
// the scheme is odd or even in the mirrored components, so the images agree to rounding.
TEST(CushionPaperSolver, MirroredIncomingBallGivesTheMirroredOutcome) {
  RandomImpacts random(kSeed + 2);
  for (int i = 0; i < 200; ++i) {
    const test::RandomImpact impact = random.next(true);
    const BallVelocity image_in = test::mirrored(impact.incoming);
    // The incoming-ball parameters of the image are the ones the derivation gives.
    const BallVelocity from_params = incomingBall(impact.speed_mps, test::kPi - impact.alpha_rad,
                                                  impact.topspin_radps, -impact.sidespin_radps);
    const double V0 = impact.speed_mps;
    EXPECT_LT(velocityDifference(image_in, from_params, impact.params.radius_m),
              kRoundoffRelative * V0);
    const CushionImpactResult direct = solvePaper(impact.params, impact.incoming, kRandomSteps);
    const CushionImpactResult image = solvePaper(impact.params, image_in, kRandomSteps);
    EXPECT_LT(velocityDifference(test::mirrored(direct.after), image.after, impact.params.radius_m),
              kRoundoffRelative * V0)
        << "impact " << i;
    EXPECT_NEAR(image.final_impulse_Ns, direct.final_impulse_Ns,
                kRoundoffRelative * direct.final_impulse_Ns);
    EXPECT_NEAR(image.compression_work_J, direct.compression_work_J,
                kRoundoffRelative * direct.compression_work_J);
  }
}

// --- 4. linear scaling
// -----------------------------------------------------------------------------

// The rates depend only on the slip directions, which do not change when every velocity is scaled
// by lambda; dP scales by lambda, so the whole run scales. With lambda a power of two the scaled
// run does the same arithmetic on scaled numbers: equal to rounding.
TEST(CushionPaperSolver, ScalingSpeedAndSpinsScalesTheOutcome) {
  RandomImpacts random(kSeed + 3);
  for (int i = 0; i < 100; ++i) {
    const test::RandomImpact impact = random.next(true);
    const CushionImpactResult base = solvePaper(impact.params, impact.incoming, kRandomSteps);
    for (double lambda : {0.25, 2.0, 8.0}) {
      BallVelocity scaled_in;
      scaled_in.v = lambda * impact.incoming.v;
      scaled_in.w = lambda * impact.incoming.w;
      const CushionImpactResult scaled = solvePaper(impact.params, scaled_in, kRandomSteps);
      BallVelocity expected;
      expected.v = lambda * base.after.v;
      expected.w = lambda * base.after.w;
      EXPECT_LT(velocityDifference(scaled.after, expected, impact.params.radius_m),
                kRoundoffRelative * lambda * impact.speed_mps)
          << "impact " << i << ", lambda " << lambda;
      EXPECT_NEAR(scaled.final_impulse_Ns, lambda * base.final_impulse_Ns,
                  kRoundoffRelative * lambda * base.final_impulse_Ns);
      EXPECT_NEAR(scaled.compression_work_J, lambda * lambda * base.compression_work_J,
                  kRoundoffRelative * lambda * lambda * base.compression_work_J);
      EXPECT_NEAR(test::reboundAngle(scaled.after), test::reboundAngle(base.after),
                  kRoundoffRelative);
    }
  }
}

// --- the Coulomb law in every increment
// ------------------------------------------------------------

// From two consecutive states, the friction impulses per unit normal impulse that produced the
// change: a at I (basis x, Y') and b at C (basis x, y), inverted from the impulse response (the
// columns for a_x, a_y, b_x, b_y). The residual of the w_y equation, which the inversion does not
// use, must vanish if the change came from contact impulses at all.
struct RecoveredFriction {
  Eigen::Vector2d cushion;  // a / dP
  Eigen::Vector2d cloth;    // b / dP
  double w_y_residual_radps_per_Ns;
};
RecoveredFriction recoverFriction(const CushionParams& p, const BallVelocity& before,
                                  const BallVelocity& after, double dP) {
  const double s = contactSinTheta(p), c = std::sqrt(1 - s * s);
  const double M = p.mass_kg, k = 5 / (2 * M * p.radius_m);
  const Eigen::Vector3d dv = (after.v - before.v) / dP, dw = (after.w - before.w) / dP;
  RecoveredFriction out;
  const double a_x = dw.z() / (k * c);
  const double b_x = -M * dv.x() - a_x;
  const double sum_y = -dw.x() / k;             // a_y + b_y
  const double difference_y = -M * dv.y() - c;  // -s a_y + b_y
  const double a_y = (sum_y - difference_y) / (1 + s);
  out.cushion = {a_x, a_y};
  out.cloth = {b_x, sum_y - a_y};
  out.w_y_residual_radps_per_Ns = dw.y() + k * (s * a_x - b_x);
  return out;
}

// Each increment applies friction mu_w along the cushion slip and mu_s (sin th + mu_w sin Phi cos
// th) along the cloth slip, both taken at the start of the increment (zero where the slip is zero).
TEST(CushionPaperSolver, EveryIncrementAppliesCoulombFrictionAlongTheSlipAtItsStart) {
  RandomImpacts random(kSeed + 4);
  for (int i = 0; i < 20; ++i) {
    const test::RandomImpact impact = random.next(true);
    const CushionParams& p = impact.params;
    const int steps = 500;
    const CushionImpactResult result = solvePaper(p, impact.incoming, steps, true);
    ASSERT_EQ(result.trace.size(), static_cast<std::size_t>(result.rhs_evaluations) + 1);
    const double dP = (1 + p.restitution) * p.mass_kg * impact.incoming.v.y() / steps;
    const double s = contactSinTheta(p), c = std::sqrt(1 - s * s);
    const double k = 5 / (2 * p.mass_kg * p.radius_m);
    for (std::size_t n = 0; n + 1 < result.trace.size(); ++n) {
      const ImpactSample& from = result.trace[n];
      const ImpactSample& to = result.trace[n + 1];
      ASSERT_NEAR(to.impulse_Ns - from.impulse_Ns, dP, kRoundoffRelative * result.final_impulse_Ns);
      const RecoveredFriction f =
          recoverFriction(p, from.ball, to.ball, to.impulse_Ns - from.impulse_Ns);
      const double tol = kRecoveredFrictionRelative;
      const Eigen::Vector2d cushion_dir = from.cushion_slip.norm() > 0
                                              ? Eigen::Vector2d(from.cushion_slip.normalized())
                                              : Eigen::Vector2d::Zero();
      const Eigen::Vector2d cloth_dir = from.cloth_slip.norm() > 0
                                            ? Eigen::Vector2d(from.cloth_slip.normalized())
                                            : Eigen::Vector2d::Zero();
      const Eigen::Vector2d expected_a = p.cushion_friction * cushion_dir;
      const Eigen::Vector2d expected_b = p.cloth_friction * (s + c * expected_a.y()) * cloth_dir;
      EXPECT_LT((f.cushion - expected_a).norm(), tol) << "increment " << n;
      EXPECT_LT((f.cloth - expected_b).norm(), tol) << "increment " << n;
      EXPECT_LT(std::abs(f.w_y_residual_radps_per_Ns), tol * k) << "increment " << n;
      EXPECT_EQ(to.ball.v.z(), 0.0);
      // The recorded slips are the model's slips of the recorded state.
      EXPECT_EQ(to.cushion_slip, cushionSlip(p, to.ball));
      EXPECT_EQ(to.cloth_slip, clothSlip(p, to.ball));
    }
    EXPECT_EQ(result.trace.front().impulse_Ns, 0.0);
    EXPECT_EQ(result.trace.back().impulse_Ns, result.final_impulse_Ns);
    expectIdentical(result.trace.back().ball, result.after);
  }
}

// --- 5. first-order convergence to the exact solver ----------------------------------------------

// The scheme's endpoint error has two first-order parts: the Euler error of the rates, smooth in
// 1/N, and the stop rules, which end compression and restitution at the first step past their
// targets, an overshoot uniform in [0, dP) that depends on where the target falls inside a step.
// The second part makes error(N) for one N wobble by up to a factor of ten (measured), so the test
// takes the worst error over kPhaseSamples consecutive N, which samples that phase; that worst
// error times N is then nearly constant (measured spread below 1.3).
constexpr int kPhaseSamples = 8;
// First order: worst-error * N may vary by at most this factor over N = 1000 ... 16000 (a second-
// order scheme would vary by 16, a zeroth-order one by 1/16).
constexpr double kFirstOrderSpread = 2.0;
// Over the 16-fold range of N the worst error must fall by a factor in [8, 32] (16 for first
// order).
constexpr double kSixteenfoldReductionLow = 8.0;
constexpr double kSixteenfoldReductionHigh = 32.0;
// The error constant itself (units of V0): the stop-rule overshoot alone reaches about
// c (1 + e) V0 / N ~ 1.8 V0 / N.
constexpr double kErrorConstantMax = 4.0;

struct ConvergenceCase {
  const char* name;
  double speed_mps, alpha_deg, topspin_per_roll, sidespin_per_roll;  // spins in units of V0 / R
};

TEST(CushionPaperSolver, ConvergesToTheExactSolverAtFirstOrder) {
  const CushionParams p;  // the paper's snooker values
  const ConvergenceCase cases[] = {{"rolling head-on", 1.0, 90, 1.0, 0.0},
                                   {"oblique with top and side spin", 1.3, 35, 0.5, -1.2},
                                   {"Fig. 10", 2.0, 45, 1.5, 2.0}};
  for (const ConvergenceCase& example : cases) {
    SCOPED_TRACE(example.name);
    const double V0 = example.speed_mps, R = p.radius_m;
    const BallVelocity in =
        incomingBall(V0, degrees(example.alpha_deg), example.topspin_per_roll * V0 / R,
                     example.sidespin_per_roll * V0 / R);
    ExactSolverOptions converged;
    converged.tolerance = 1e-14;
    const BallVelocity reference = solveCushionImpactExact(p, in, converged).after;
    std::vector<double> scaled_error;  // worst error over the phase samples, times N, over V0
    for (int N = 1000; N <= 16000; N *= 2) {
      double worst = 0;
      for (int j = 0; j < kPhaseSamples; ++j) {
        worst = std::max(worst, velocityDifference(solvePaper(p, in, N + j).after, reference, R));
      }
      scaled_error.push_back(worst * N / V0);
    }
    const auto [low, high] = std::minmax_element(scaled_error.begin(), scaled_error.end());
    EXPECT_LE(*high / *low, kFirstOrderSpread) << ::testing::PrintToString(scaled_error);
    EXPECT_LE(*high, kErrorConstantMax) << ::testing::PrintToString(scaled_error);
    const double reduction = 16 * scaled_error.front() / scaled_error.back();
    EXPECT_GE(reduction, kSixteenfoldReductionLow) << ::testing::PrintToString(scaled_error);
    EXPECT_LE(reduction, kSixteenfoldReductionHigh) << ::testing::PrintToString(scaled_error);
  }
}

// With the stop rules located by interpolation (test::paperSchemeWithLocatedStops) only the Euler
// error of the trajectory is left, which is C / N + O(1/N^2) while the slip directions turn
// smoothly: halving the step halves the error. (Not for the rolling head-on case: there the cushion
// slip passes through zero and reverses, and the increment in which friction flips is again a
// phase-dependent first-order error.)
constexpr double kHalvingRatioLow = 1.9;  // error(N) / error(2N) for a first-order method: 2
constexpr double kHalvingRatioHigh = 2.1;

TEST(CushionPaperSolver, EulerTrajectoryWithLocatedStopsHalvesItsErrorWithItsStep) {
  const CushionParams p;
  const ConvergenceCase cases[] = {{"oblique with top and side spin", 1.3, 35, 0.5, -1.2},
                                   {"Fig. 10", 2.0, 45, 1.5, 2.0}};
  for (const ConvergenceCase& example : cases) {
    SCOPED_TRACE(example.name);
    const double V0 = example.speed_mps, R = p.radius_m;
    const BallVelocity in =
        incomingBall(V0, degrees(example.alpha_deg), example.topspin_per_roll * V0 / R,
                     example.sidespin_per_roll * V0 / R);
    ExactSolverOptions converged;
    converged.tolerance = 1e-14;
    const BallVelocity reference = solveCushionImpactExact(p, in, converged).after;
    double previous = 0;
    for (int N = 1000; N <= 16000; N *= 2) {
      double error;
      {
        FloatingPointTraps traps;
        error = velocityDifference(test::paperSchemeWithLocatedStops(p, in, N), reference, R);
      }
      EXPECT_LE(error * N / V0, kErrorConstantMax) << "N " << N;
      if (N > 1000) {
        EXPECT_GE(previous / error, kHalvingRatioLow) << "N " << N;
        EXPECT_LE(previous / error, kHalvingRatioHigh) << "N " << N;
      }
      previous = error;
    }
  }
}

// --- 8. the publication's head-on rolling rebound
// -------------------------------------------------

// The paper's setting N = 5000 reproduces the model's head-on rolling ratio of about 0.91
// (physics-notes section 1: 0.818 is a fit over speeds where the rigid model fails).
constexpr double kHeadOnRatioLow = 0.89;
constexpr double kHeadOnRatioHigh = 0.93;

TEST(CushionPaperSolver, PublicationSettingGivesTheHeadOnRollingRatio) {
  const CushionParams p;
  for (double V0 : {0.5, 1.0, 2.0}) {
    const CushionImpactResult result =
        solvePaper(p, incomingBall(V0, degrees(90), V0 / p.radius_m, 0), 5000);
    const double ratio = test::reboundSpeed(result.after) / V0;
    EXPECT_GE(ratio, kHeadOnRatioLow) << "V0 " << V0;
    EXPECT_LE(ratio, kHeadOnRatioHigh) << "V0 " << V0;
    EXPECT_NEAR(result.after.v.x(), 0.0, kRoundoffRelative * V0)
        << "head-on without side stays head-on";
  }
}

// --- determinism and options
// ----------------------------------------------------------------------

TEST(CushionPaperSolver, SameInputGivesBitIdenticalOutput) {
  RandomImpacts random(kSeed + 5);
  for (int i = 0; i < 20; ++i) {
    const test::RandomImpact impact = random.next(true);
    const CushionImpactResult first = solvePaper(impact.params, impact.incoming, 1000, true);
    const CushionImpactResult second = solvePaper(impact.params, impact.incoming, 1000, true);
    expectIdentical(first.after, second.after);
    EXPECT_EQ(first.compression_impulse_Ns, second.compression_impulse_Ns);
    EXPECT_EQ(first.final_impulse_Ns, second.final_impulse_Ns);
    EXPECT_EQ(first.compression_work_J, second.compression_work_J);
    EXPECT_EQ(first.rhs_evaluations, second.rhs_evaluations);
    ASSERT_EQ(first.trace.size(), second.trace.size());
    for (std::size_t n = 0; n < first.trace.size(); ++n) {
      expectIdentical(first.trace[n].ball, second.trace[n].ball);
      EXPECT_EQ(first.trace[n].normal_work_J, second.trace[n].normal_work_J);
    }
  }
}

TEST(CushionPaperSolver, TraceIsOnlyRecordedWhenAsked) {
  const CushionParams p;
  const BallVelocity in = incomingBall(1.0, degrees(60), 0, 0);
  EXPECT_TRUE(solvePaper(p, in, 100).trace.empty());
  const CushionImpactResult traced = solvePaper(p, in, 100, true);
  EXPECT_EQ(traced.trace.size(), static_cast<std::size_t>(traced.rhs_evaluations) + 1);
  // W_c is the recorded work at the first increment that ends with v_y <= 0, and the run stops at
  // the first increment whose work is down to (1 - e^2) W_c.
  const auto crossing =
      std::find_if(traced.trace.begin(), traced.trace.end(),
                   [](const ImpactSample& sample) { return sample.ball.v.y() <= 0; });
  ASSERT_NE(crossing, traced.trace.end());
  EXPECT_EQ(crossing->impulse_Ns, traced.compression_impulse_Ns);
  EXPECT_EQ(crossing->normal_work_J, traced.compression_work_J);
  const double target = (1 - p.restitution * p.restitution) * traced.compression_work_J;
  EXPECT_LE(traced.trace.back().normal_work_J, target);
  EXPECT_GT(traced.trace[traced.trace.size() - 2].normal_work_J, target);
}

TEST(CushionPaperSolver, RejectsBadStepsParametersAndIncomingBalls) {
  const CushionParams p;
  const BallVelocity in = incomingBall(1.0, degrees(60), 0, 0);
  for (int steps : {0, -5, std::numeric_limits<int>::min(), kMaxPaperSteps + 1,
                    std::numeric_limits<int>::max()}) {
    PaperSolverOptions options;
    options.steps = steps;
    expectRejected([&] { solveCushionImpactPaper(p, in, options); },
                   {"steps = " + std::to_string(steps) + " ", "it must lie in [1, 10000000]"});
  }
  PaperSolverOptions one_step;
  one_step.steps = 1;
  EXPECT_NO_THROW(solveCushionImpactPaper(p, in, one_step));
  // The solver validates its inputs (the validation itself is tested with the model).
  CushionParams bad = p;
  bad.restitution = 1.5;
  expectRejected([&] { solveCushionImpactPaper(bad, in); }, {"e_e = 1.5"});
  bad = p;
  bad.cushion_friction = std::numeric_limits<double>::quiet_NaN();
  expectRejected([&] { solveCushionImpactPaper(bad, in); }, {"mu_w = nan"});
  BallVelocity leaving = in;
  leaving.v.y() = -0.5;
  expectRejected([&] { solveCushionImpactPaper(p, leaving); }, {"v_y", "= -0.5"});
  BallVelocity spinning_nan = in;
  spinning_nan.w.z() = std::numeric_limits<double>::infinity();
  expectRejected([&] { solveCushionImpactPaper(p, spinning_nan); }, {"w_z", "= inf"});
}

}  // namespace
}  // namespace baize::physics
