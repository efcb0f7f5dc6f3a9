#include "engine/sim/broad_phase.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <vector>

namespace baize::engine {
namespace {

using Eigen::Vector2d;

// Points sampled along a path this finely: far finer than the paths' curvature at these sizes.
constexpr int kSamples = 2000;

struct Draw {
  std::mt19937_64 random{20261129};
  double uniform(double lo, double hi) { return lo + (hi - lo) * ((random() >> 11) * 0x1.0p-53); }
  physics::PositionQuadratic path() {
    physics::PositionQuadratic p;
    p.constant_m = Vector2d(uniform(-1, 1), uniform(-0.5, 0.5));
    p.linear_mps = Vector2d(uniform(-3, 3), uniform(-3, 3));
    p.quadratic_mps2 = Vector2d(uniform(-2, 2), uniform(-2, 2));
    return p;
  }
};

// The swept box holds every centre along the path, grown by the radius.
TEST(BroadPhase, ASweptBoxHoldsTheBallAlongItsWholePath) {
  Draw draw;
  const double R = 0.028575;
  for (int k = 0; k < 200; ++k) {
    const physics::PositionQuadratic path = draw.path();
    const double duration = draw.uniform(0.01, 3);
    const Box box = sweptBox(path, duration, R);
    for (int s = 0; s <= kSamples; ++s) {
      const Vector2d q = path.at(duration * s / kSamples);
      for (int axis = 0; axis < 2; ++axis) {
        EXPECT_LE(box.lo[axis], q[axis] - R) << "path " << k;
        EXPECT_GE(box.hi[axis], q[axis] + R) << "path " << k;
      }
    }
  }
  // A path of no end covers everything.
  const Box all = sweptBox(draw.path(), std::numeric_limits<double>::infinity(), R);
  EXPECT_TRUE(all.overlaps(Box::around(Vector2d(1e6, -1e6), R)));
}

// The cheap bounds never drop a contact: where a sampled gap closes, staysFarther and staysApart
// must both say "maybe" (false).
TEST(BroadPhase, TheBoundsNeverClaimAClosingGapStaysOpen) {
  Draw draw;
  int closing = 0, skipped = 0;
  for (int k = 0; k < 2000; ++k) {
    const physics::PositionQuadratic path = draw.path();
    const Vector2d centre(draw.uniform(-1, 1), draw.uniform(-0.5, 0.5));
    const double distance = draw.uniform(0.02, 0.3), horizon = draw.uniform(0.01, 1);
    bool closes = false;
    for (int s = 0; s <= kSamples && !closes; ++s)
      closes = (path.at(horizon * s / kSamples) - centre).norm() < distance;
    const bool farther = staysFarther(path.constant_m - centre, path.linear_mps,
                                      path.quadratic_mps2, distance, horizon);
    const physics::PolynomialCoefficients gap =
        squaredGap(path, centre, Vector2d::Zero(), Vector2d::Zero(), distance);
    const bool apart = staysApart(gap, horizon);
    if (closes) {
      ++closing;
      EXPECT_FALSE(farther) << "draw " << k;
      EXPECT_FALSE(apart) << "draw " << k;
    } else {
      skipped += farther || apart;
    }
  }
  EXPECT_GT(closing, 100);  // both kinds of draw are common
  EXPECT_GT(skipped, 100);  // and the bounds do skip work
}

// Balls that pass 5 mm wide of touching over a long horizon: the coefficient bound cannot show the
// gap stays open, the Bernstein coefficients can; 1 mm closer than touching, neither claims it.
TEST(BroadPhase, BernsteinCoefficientsShowAWidePassStaysOpen) {
  physics::PositionQuadratic path;
  path.constant_m = Vector2d(-1, 0.0625);
  path.linear_mps = Vector2d(1, 0);
  const double touching = 0.0575, horizon = 2;
  const physics::PolynomialCoefficients wide =
      squaredGap(path, Vector2d::Zero(), Vector2d::Zero(), Vector2d::Zero(), touching);
  double loose = wide[0], power = 1;
  for (int k = 1; k < 5; ++k) loose -= std::abs(wide[k]) * (power *= horizon);
  EXPECT_LE(loose, 0) << "the premise: the coefficient bound fails here";
  EXPECT_TRUE(bernsteinStaysPositive(wide, horizon));
  EXPECT_TRUE(staysApart(wide, horizon));
  const physics::PolynomialCoefficients overlapping =
      squaredGap(path, Vector2d::Zero(), Vector2d::Zero(), Vector2d::Zero(), 0.0635);
  EXPECT_FALSE(bernsteinStaysPositive(overlapping, horizon));
  EXPECT_FALSE(staysApart(overlapping, horizon));
}

// A contact just resolved: the gap starts at zero (within rounding). Where opensThroughout() says it
// only opens, the root finder finds no closing root either; a gap that closes at the start, or turns
// back and closes within the horizon, is never claimed.
TEST(BroadPhase, AGapSaidToOpenThroughoutHasNoClosingRoot) {
  Draw draw;
  int opening = 0, closing = 0;
  for (int k = 0; k < 4000; ++k) {
    physics::PositionQuadratic path = draw.path();
    const double distance = draw.uniform(0.02, 0.3), horizon = draw.uniform(0.01, 2);
    const double angle = draw.uniform(0, 2 * M_PI);
    path.constant_m = distance * Vector2d(std::cos(angle), std::sin(angle));  // touching
    physics::PolynomialCoefficients gap =
        squaredGap(path, Vector2d::Zero(), Vector2d::Zero(), Vector2d::Zero(), distance);
    if (k % 2) gap = {gap[0], gap[1], gap[2], 0, 0};  // a straight cushion's kind of gap
    const bool opens = opensThroughout(gap, horizon);
    const physics::RootSearchResult hit = physics::firstClosingRoot(gap, 0, horizon);
    if (opens) {
      ++opening;
      EXPECT_EQ(hit.outcome, physics::RootOutcome::NoRoot) << "draw " << k;
    }
    closing += hit.outcome == physics::RootOutcome::Root;
  }
  EXPECT_GT(opening, 500);  // separating contacts are common
  EXPECT_GT(closing, 500);  // and so are closing ones, never claimed
  const physics::PolynomialCoefficients turns_back = {0, 1, -4, 0, 0};  // opens, closes at 0.25
  EXPECT_FALSE(opensThroughout(turns_back, 1));
  EXPECT_TRUE(opensThroughout(turns_back, 0.1));
}

// Gaps whose slope is positive at both ends and whose value at the horizon is positive, but which
// close on the way (or touch, or start flat): never claimed, and the root finder finds the close.
TEST(BroadPhase, AGapOpenAtBothEndsThatClosesOnTheWayIsNotSaidToOpen) {
  // t (t - 0.4) (t - 0.6): slope 0.24 at 0 and 1.24 at 1, value 0.24 at 1; closes at 0.4.
  const physics::PolynomialCoefficients dips = {0, 0.24, -1, 1, 0};
  EXPECT_FALSE(opensThroughout(dips, 1));
  const physics::RootSearchResult dip = physics::firstClosingRoot(dips, 0, 1);
  ASSERT_EQ(dip.outcome, physics::RootOutcome::Root);
  EXPECT_NEAR(dip.time, 0.4, 1e-12);
  // t (t - 0.5)^2: touches again at 0.5 (a double root).
  const physics::PolynomialCoefficients touches = {0, 0.25, -1, 1, 0};
  EXPECT_FALSE(opensThroughout(touches, 1));
  EXPECT_EQ(physics::firstClosingRoot(touches, 0, 1).outcome, physics::RootOutcome::Root);
  // Flat at the start: no proof that it opens.
  EXPECT_FALSE(opensThroughout({0, 0, 1, 0, 0}, 1));
  // A value at the horizon far below its coefficients' scale (a subnormal horizon) is not trusted:
  // the root finder, which scales the polynomial first, would read it as zero.
  EXPECT_FALSE(opensThroughout({0, 1, 0, 0, 0x1p20}, 1e-318));
  EXPECT_TRUE(opensThroughout({0, 1, 0, 0, 0x1p20}, 1e-3));
}

// The gap polynomial is |c + l t + q t^2 - centre|^2 - d^2, coefficient by coefficient.
TEST(BroadPhase, TheSquaredGapIsTheDistancePolynomial) {
  Draw draw;
  const physics::PositionQuadratic path = draw.path();
  const Vector2d centre(0.1, 0.2);
  const physics::PolynomialCoefficients p =
      squaredGap(path, centre, Vector2d::Zero(), Vector2d::Zero(), 0.05);
  for (double t : {0.0, 0.3, 1.1}) {
    const double value = p[0] + t * (p[1] + t * (p[2] + t * (p[3] + t * p[4])));
    EXPECT_NEAR(value, (path.at(t) - centre).squaredNorm() - 0.05 * 0.05, 1e-12);
  }
}

// The grid of resting balls visits every ball within reach of a box, each once.
TEST(BroadPhase, TheRestingGridVisitsEveryBallWithinReachOnce) {
  Draw draw;
  const double R = 0.028575;
  std::vector<physics::BallState> balls(300);
  std::vector<int> indices;
  for (int i = 0; i < 300; ++i) {
    balls[i].position = Vector2d(draw.uniform(-1.2, 1.2), draw.uniform(-0.6, 0.6));
    if (i % 3 != 0) indices.push_back(i);  // the grid holds only the ones given
  }
  const RestingGrid grid(indices, balls, R);
  for (int k = 0; k < 100; ++k) {
    const Box box = sweptBox(draw.path(), draw.uniform(0.01, 0.3), R);
    const double reach = R + kBoxMargin_m;
    std::multiset<int> visited;
    grid.forEachNear(box, reach, [&](int i) { visited.insert(i); });
    for (int i : indices) {
      EXPECT_LE(visited.count(i), 1u);
      const Vector2d& q = balls[i].position;
      const bool near = q.x() >= box.lo.x() - reach && q.x() <= box.hi.x() + reach &&
                        q.y() >= box.lo.y() - reach && q.y() <= box.hi.y() + reach;
      if (near) {
        EXPECT_EQ(visited.count(i), 1u) << "ball " << i << ", box " << k;
      }
    }
    for (int i : visited) EXPECT_NE(i % 3, 0) << "ball " << i << " is not in the grid";
  }
  int none = 0;
  RestingGrid().forEachNear(Box::around(Vector2d::Zero(), 1), 1, [&](int) { ++none; });
  EXPECT_EQ(none, 0);
}

}  // namespace
}  // namespace baize::engine
