#include "physics/cue_strike.h"

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
#include <utility>
#include <vector>

#include "tests/physics/rejection_test_support.h"

namespace baize::physics {
namespace {

using Eigen::Vector3d;
using test::expectValueRejected;
using ::testing::HasSubstr;

constexpr double kPi = 3.14159265358979323846;
// Closed-form results: a few dozen operations, so a few ulp of the scale they are compared at.
constexpr double kRelative = 1e-13;

Vector3d aimOf(double heading) { return {std::cos(heading), std::sin(heading), 0}; }

double ballEnergy(const CueStrikeParams& p, const Vector3d& v, const Vector3d& w) {
  const double R = p.ball_radius_m;
  return 0.5 * p.ball_mass_kg * v.squaredNorm() + 0.2 * p.ball_mass_kg * R * R * w.squaredNorm();
}

// Ball velocity before the cloth removed its vertical part (no squirt).
Vector3d fullVelocity(const CueStrikeResult& r) {
  return r.ball.v + r.discarded_vertical_velocity_mps * Vector3d::UnitZ();
}

struct Random {
  std::mt19937_64 engine;
  explicit Random(std::uint64_t seed) : engine(seed) {}
  double unit() { return static_cast<double>(engine() >> 11) * 0x1.0p-53; }  // [0, 1)
};

CueShot randomShot(Random& r) {
  CueShot s;
  s.speed_mps = 8 * r.unit();
  s.heading_rad = 2 * kPi * r.unit();
  // Up to 57 deg: with offsets within the miscue limit every such cue can reach its contact point
  // (c cos(theta) + b sin(theta) > 0 needs tan(theta) < sqrt(3) when b = -0.5).
  s.elevation_rad = 1.0 * r.unit();
  const double radius = kMiscueOffsetLimit * std::sqrt(r.unit()), angle = 2 * kPi * r.unit();
  s.side_offset = radius * std::cos(angle);
  s.height_offset = radius * std::sin(angle);
  return s;
}

TEST(CueStrike, CentreHitWithHeavyElasticCueGivesOneAndAHalfTimesTheCueSpeed) {
  CueStrikeParams p;
  p.cue_mass_kg = 3 * p.ball_mass_kg;
  p.tip_restitution = 1;
  for (double heading : {0.0, 0.7, 2.0, -2.9}) {
    CueShot s;
    s.speed_mps = 2.0;
    s.heading_rad = heading;
    const CueStrikeResult r = strikeCueBall(p, s);
    // Elastic 1-D collision: v = 2 m_c V / (m_c + m) = 1.5 V.
    EXPECT_LE((r.ball.v - 3.0 * aimOf(heading)).norm(), kRelative * 3);
    EXPECT_LE(p.ball_radius_m * r.ball.w.norm(), kRelative * 3);
    EXPECT_NEAR(r.cue_speed_after_mps, 1.0, kRelative);  // V (m_c - m) / (m_c + m)
  }
}

TEST(CueStrike, FourTenthsAboveCentreGivesNaturalRollAtAnySpeed) {
  const CueStrikeParams p;
  const double R = p.ball_radius_m;
  for (double speed : {0.3, 1.0, 3.0, 8.0, 16.0}) {
    CueShot s;
    s.speed_mps = speed;
    s.heading_rad = 0.9;
    s.height_offset = 0.4;
    const CueStrikeResult r = strikeCueBall(p, s);
    // Slip of the cloth contact point C = -R z: v + w x (-R z).
    const Vector3d slip = r.ball.v + r.ball.w.cross(-R * Vector3d::UnitZ());
    EXPECT_LE(slip.norm(), kRelative * r.ball.v.norm());
    EXPECT_NEAR(R * r.ball.w.norm(), r.ball.v.norm(), kRelative * r.ball.v.norm());
    EXPECT_GT(r.ball.v.norm(), 0.0);
  }
  // And only there: slightly lower leaves the ball sliding forward of its roll.
  CueShot low;
  low.speed_mps = 2;
  low.height_offset = 0.3;
  const CueStrikeResult r = strikeCueBall(p, low);
  EXPECT_GT((r.ball.v + r.ball.w.cross(-R * Vector3d::UnitZ())).x(), 0.0);
}

TEST(CueStrike, RightEnglishSpinsCounterClockwiseAndKeepsTheBallOnTheCueLine) {
  const CueStrikeParams p;  // no squirt
  for (double heading : {0.0, 1.1, -2.5}) {
    for (double side : {0.3, -0.3}) {
      CueShot s;
      s.speed_mps = 1.5;
      s.heading_rad = heading;
      s.side_offset = side;
      const CueStrikeResult r = strikeCueBall(p, s);
      // Right english (a > 0, right of centre looking along the cue): w_z > 0, counter-clockwise
      // seen from above; left english the opposite. No top or back spin from a level side hit.
      EXPECT_EQ(r.ball.w.z() > 0, side > 0);
      EXPECT_LE(std::abs(r.ball.w.dot(aimOf(heading).cross(Vector3d::UnitZ()))),
                kRelative * r.ball.w.norm());
      // The velocity stays along the cue.
      EXPECT_LE(r.ball.v.cross(aimOf(heading)).norm(), kRelative * r.ball.v.norm());
      EXPECT_GT(r.ball.v.dot(aimOf(heading)), 0.0);
      EXPECT_EQ(r.squirt_angle_rad, 0.0);
    }
  }
}

TEST(CueStrike, SquirtTurnsTheBallAwayFromTheOffsetSide) {
  CueStrikeParams plain;
  CueStrikeParams squirting = plain;
  squirting.end_mass_kg = 0.010;
  for (double side : {0.45, 0.2, -0.2, -0.45}) {
    CueShot s;
    s.speed_mps = 2.0;
    s.heading_rad = 0.4;
    s.side_offset = side;
    const CueStrikeResult a = strikeCueBall(plain, s);
    const CueStrikeResult b = strikeCueBall(squirting, s);
    // physics-notes section 4: tan(alpha) = (5/2) b_r sqrt(1 - b_r^2) / (1 + m/m_end + (5/2)(1 -
    // b_r^2)).
    const double q = 1 - side * side;
    const double expected = std::atan(2.5 * side * std::sqrt(q) / (1 + 0.170 / 0.010 + 2.5 * q));
    const Vector3d aim = aimOf(0.4);
    const double turned = std::atan2(aim.cross(b.ball.v).z(), aim.dot(b.ball.v));  // + = left
    EXPECT_NEAR(turned, expected, 1e-12);
    EXPECT_NEAR(b.squirt_angle_rad, expected, 1e-15);
    EXPECT_EQ(turned > 0, side > 0);  // right english (a > 0) squirts the ball to the left
    EXPECT_NEAR(b.ball.v.norm(), a.ball.v.norm(), kRelative * a.ball.v.norm());
    EXPECT_LE((b.ball.w - a.ball.w).norm(), kRelative * a.ball.w.norm());
    EXPECT_GT(std::abs(turned), 0.005);  // rad: squirt of a few tenths of a degree or more
  }
}

TEST(CueStrike, LinearInCueSpeed) {
  const CueStrikeParams p;
  Random rng(5);
  for (int k = 0; k < 200; ++k) {
    CueShot s = randomShot(rng);
    s.speed_mps = 1.0;
    const CueStrikeResult one = strikeCueBall(p, s);
    for (double speed : {0.25, 3.0, 12.0}) {
      s.speed_mps = speed;
      const CueStrikeResult r = strikeCueBall(p, s);
      EXPECT_LE((r.ball.v - speed * one.ball.v).norm(), kRelative * speed * one.ball.v.norm());
      EXPECT_LE((r.ball.w - speed * one.ball.w).norm(),
                kRelative * speed * one.ball.w.norm() + 1e-300);
    }
  }
}

TEST(CueStrike, BallNeverGetsMoreEnergyThanTheCueGaveUp) {
  Random rng(6);
  for (int k = 0; k < 2000; ++k) {
    CueStrikeParams p;
    p.cue_mass_kg = 0.3 + 0.5 * rng.unit();
    p.tip_restitution = rng.unit();
    const CueShot s = randomShot(rng);
    const CueStrikeResult r = strikeCueBall(p, s);
    const double delivered =
        0.5 * p.cue_mass_kg *
        (s.speed_mps * s.speed_mps - r.cue_speed_after_mps * r.cue_speed_after_mps);
    const double scale = 0.5 * p.cue_mass_kg * s.speed_mps * s.speed_mps;
    EXPECT_LE(ballEnergy(p, fullVelocity(r), r.ball.w), delivered + kRelative * scale);
    EXPECT_LE(ballEnergy(p, r.ball.v, r.ball.w),
              ballEnergy(p, fullVelocity(r), r.ball.w) + kRelative * scale);
  }
}

TEST(CueStrike, ElasticTipConservesEnergyAndSatisfiesNewtonsLawAtTheTip) {
  // With e_tip = 1 the cue's lost energy all goes into the ball (before the cloth takes v_z), and
  // the tip point separates at e_tip V: (v + w x Q) . d - V' = e_tip V. Both check the impulse
  // formula, including its cue-line distance, against the geometry of Q and d.
  Random rng(7);
  for (int k = 0; k < 1000; ++k) {
    CueStrikeParams p;
    p.tip_restitution = k % 2 == 0 ? 1.0 : rng.unit();
    const CueShot s = randomShot(rng);
    const CueStrikeResult r = strikeCueBall(p, s);
    const double scale = 0.5 * p.cue_mass_kg * s.speed_mps * s.speed_mps;
    const Vector3d tip_point_velocity = fullVelocity(r) + r.ball.w.cross(r.contact_point_m);
    EXPECT_NEAR(tip_point_velocity.dot(r.cue_axis) - r.cue_speed_after_mps,
                p.tip_restitution * s.speed_mps, kRelative * 10 * s.speed_mps);
    if (p.tip_restitution == 1.0) {
      const double delivered =
          0.5 * p.cue_mass_kg *
          (s.speed_mps * s.speed_mps - r.cue_speed_after_mps * r.cue_speed_after_mps);
      EXPECT_NEAR(ballEnergy(p, fullVelocity(r), r.ball.w), delivered, kRelative * 10 * scale);
    }
  }
}

TEST(CueStrike, ContactGeometry) {
  const CueStrikeParams p;
  const double R = p.ball_radius_m;
  Random rng(8);
  for (int k = 0; k < 500; ++k) {
    const CueShot s = randomShot(rng);
    const CueStrikeResult r = strikeCueBall(p, s);
    EXPECT_NEAR(r.contact_point_m.norm(), R, kRelative * R);                 // Q on the ball
    EXPECT_NEAR(r.contact_point_m.z(), s.height_offset * R, kRelative * R);  // b is a height
    EXPECT_LT(r.contact_point_m.dot(r.cue_axis), 0.0);                       // Q faces the cue
    EXPECT_NEAR(r.cue_axis.z(), -std::sin(s.elevation_rad), kRelative);      // the cue points down
    // The cue line's distance from the centre, computed from the geometry.
    EXPECT_NEAR(r.cue_line_offset_m, r.contact_point_m.cross(r.cue_axis).norm(), kRelative * R);
    // The cloth takes the downward part.
    EXPECT_EQ(r.ball.v.z(), 0.0);
    EXPECT_NEAR(r.discarded_vertical_velocity_mps,
                -r.impulse_Ns * std::sin(s.elevation_rad) / p.ball_mass_kg, kRelative * 20);
  }
  // A high hit with the cue raised to tan(theta) = b / c sends the cue line through the centre
  // (the cross term cancels b): no spin, and the same impulse as a centre hit.
  CueShot high;
  high.speed_mps = 2;
  high.height_offset = 0.3;
  high.elevation_rad = std::atan(0.3 / std::sqrt(1 - 0.09));
  const CueStrikeResult through = strikeCueBall(p, high);
  EXPECT_LE(through.cue_line_offset_m, kRelative * R);
  EXPECT_LE(R * through.ball.w.norm(), kRelative * 2);
  CueShot centre;
  centre.speed_mps = 2;
  EXPECT_NEAR(through.impulse_Ns, strikeCueBall(p, centre).impulse_Ns, kRelative);
  // An elevated centre-line hit at the equator passes below the centre: draw (w along +right).
  CueShot elevated;
  elevated.speed_mps = 2;
  elevated.elevation_rad = 0.3;
  const CueStrikeResult draw = strikeCueBall(p, elevated);
  EXPECT_NEAR(draw.cue_line_offset_m, R * std::sin(0.3), kRelative * R);
  EXPECT_GT(draw.ball.w.dot(aimOf(0).cross(Vector3d::UnitZ())), 0.0);
}

TEST(CueStrike, RejectsBadShots) {
  const CueStrikeParams p;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto shot = [&](const std::function<void(CueShot&)>& change) {
    CueShot s;
    s.speed_mps = 1;
    change(s);
    return [=] { strikeCueBall(p, s); };
  };
  expectValueRejected(shot([&](CueShot& s) { s.speed_mps = nan; }), "cue speed V (m/s) = nan");
  expectValueRejected(shot([](CueShot& s) { s.speed_mps = -0.5; }), "cue speed V (m/s) = -0.5");
  expectValueRejected(shot([&](CueShot& s) { s.heading_rad = INFINITY; }), "cue heading phi (rad)");
  expectValueRejected(shot([](CueShot& s) { s.elevation_rad = -0.1; }),
                      "cue elevation theta (rad)");
  expectValueRejected(shot([](CueShot& s) { s.elevation_rad = kPi / 2; }),
                      "cue elevation theta (rad)");
  expectValueRejected(shot([&](CueShot& s) { s.side_offset = nan; }), "tip side offset a");
  // Miscue: offset just above the limit, in either direction.
  expectValueRejected(shot([](CueShot& s) { s.side_offset = 0.51; }), "miscues");
  expectValueRejected(shot([](CueShot& s) { s.side_offset = 0.36, s.height_offset = -0.36; }),
                      "miscues");
  // A steep cue cannot reach a low contact point from behind.
  expectValueRejected(shot([](CueShot& s) { s.height_offset = -0.5, s.elevation_rad = 1.5; }),
                      "the cue line meets the ball behind");
  // The limit itself is allowed.
  EXPECT_NO_THROW(shot([](CueShot& s) { s.side_offset = kMiscueOffsetLimit; })());
}

TEST(CueStrike, RejectsBadParameters) {
  auto params = [](const std::function<void(CueStrikeParams&)>& change) {
    CueStrikeParams p;
    change(p);
    CueShot s;
    s.speed_mps = 1;
    return [=] { strikeCueBall(p, s); };
  };
  expectValueRejected(params([](CueStrikeParams& p) { p.cue_mass_kg = 0; }), "cue mass (kg) = 0");
  expectValueRejected(params([](CueStrikeParams& p) { p.tip_restitution = 1.5; }),
                      "cue tip restitution e_tip = 1.5");
  expectValueRejected(params([](CueStrikeParams& p) { p.ball_mass_kg = -1; }),
                      "ball mass (kg) = -1");
  expectValueRejected(params([](CueStrikeParams& p) { p.ball_radius_m = std::nan(""); }),
                      "ball radius (m)");
  expectValueRejected(params([](CueStrikeParams& p) { p.end_mass_kg = 0.0; }),
                      "cue end mass (kg) = 0");
}

// cueMeetsTipPointFirst decides as strikeCueBall does, on either side of the steepest elevation
// below the centre; at or above the centre every elevation below vertical is reachable.
TEST(CueStrike, TheSteepestElevationSeparatesReachableFromUnreachableTipPoints) {
  const CueStrikeParams params;
  const std::vector<std::pair<double, double>> below_centre = {
      {0.0, -0.4}, {0.3, -0.35}, {-0.2, -0.1}, {0.0, -0.5}};
  for (const auto& [a, b] : below_centre) {
    const double steepest = steepestCueElevationRad(a, b);
    EXPECT_NEAR(std::tan(steepest), std::sqrt(1 - a * a - b * b) / -b, kRelative * 10);
    for (const double theta :
         {0.0, steepest - 1e-12, steepest + 1e-12, std::nextafter(kPi / 2, 0.0)}) {
      CueShot shot;
      shot.speed_mps = 1;
      shot.side_offset = a;
      shot.height_offset = b;
      shot.elevation_rad = theta;
      const bool meets = cueMeetsTipPointFirst(shot);
      EXPECT_EQ(meets, theta < steepest) << "a " << a << ", b " << b << ", theta " << theta;
      bool struck = true;
      try {
        strikeCueBall(params, shot);
      } catch (const std::invalid_argument&) {
        struck = false;
      }
      EXPECT_EQ(struck, meets) << "a " << a << ", b " << b << ", theta " << theta;
    }
  }
  EXPECT_EQ(steepestCueElevationRad(0.3, 0.2), kPi / 2);
  EXPECT_EQ(steepestCueElevationRad(0, 0), kPi / 2);
}

}  // namespace
}  // namespace baize::physics
