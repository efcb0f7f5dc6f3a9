// "No missed events": the event loop's exact-root contact times against an independent brute force.
//
// The brute force knows nothing of polynomials: it moves every ball on its own with
// physics::advance (the closed form of a lone ball, exact between contacts) and samples every pair
// of balls and every ball and cushion, jaw rounding and pocket capture circle every kStep_s,
// refining between samples by bisection (a crossing) and golden- section search (a dip between
// samples, as in a grazing pass). Between two consecutive contact events of the loop it must see
//   - no penetration (a gap below -kPenetrationTolerance_m) before the next event's time - step,
//   - a touch (a gap at or below +kTouchTolerance_m) no later than that time + step,
// and the event's own pair or ball and cushion must be touching at the reported time. Each interval
// starts from the loop's post-event states, so the whole shot is checked event by event.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "engine/io/table.h"
#include "engine/models/model_registry.h"
#include "engine/sim/shot_simulator.h"

namespace baize::engine {
namespace {

using physics::BallState;

constexpr double kTableLength_m = 2.54;
constexpr double kTableWidth_m = 1.27;
// Brute-force sampling step, s: at 4 m/s a ball moves 0.4 mm per step; the bisection and the
// golden-section search between samples find crossings and dips the samples straddle.
constexpr double kStep_s = 1e-4;
// The refined step of the second pass, s.
constexpr double kFineStep_s = 1e-5;
// An overlap beyond this counts as a contact the loop missed, m: positions are rounded to ~1e-15 m
// and the loop's roots to its rounding band (~1e-14 m), far below; any visible overlap far above.
constexpr double kPenetrationTolerance_m = 1e-9;
// A gap at or below this counts as touching, m (the same reasoning as the penetration tolerance).
constexpr double kTouchTolerance_m = 1e-9;
// Each scene is checked over this much of the shot, s: enough for several contacts per scene
// while keeping the whole test to a few seconds.
constexpr double kCheckedSpan_s = 1.5;
// No ball in these scenes exceeds this speed, m/s (cue balls up to 4 m/s, gaining at most half
// again from spin): a gap can dip at most 2 of these times a step below its samples.
constexpr double kSpeedBound_mps = 10.0;
// Golden-section iterations: shrink a 2-step bracket by 0.618^80, below 1e-20 s.
constexpr int kGoldenIterations = 80;
// Bisection iterations: halve a step 60 times, below 1e-21 s.
constexpr int kBisectionIterations = 60;

const double kInf = std::numeric_limits<double>::infinity();

// A pair of balls (other >= 0), a ball and a cushion (cushion >= 0), a ball and a jaw's rounding
// (jaw >= 0), or a ball's centre and a pocket's capture circle (pocket >= 0: it falls in there).
struct Contact {
  int ball = 0, other = -1, cushion = -1, jaw = -1, pocket = -1;
};

struct Checker {
  SimulationParams params = poolSimulationParams();
  TableGeometry table = rectangularTable(kTableLength_m, kTableWidth_m);
  double R = params.ball.radius_m;

  Checker() = default;
  explicit Checker(TableGeometry geometry) : table(std::move(geometry)) {}

  // The gap of a contact when the balls are `states`, m; +infinity for a ball beside the cushion's
  // ends or outside the jaw rounding's arc (it cannot touch that cushion or arc there).
  double gap(const Contact& c, const std::vector<BallState>& states) const {
    const Eigen::Vector2d p = states[c.ball].position;
    if (c.other >= 0) return (p - states[c.other].position).norm() - 2 * R;
    if (c.pocket >= 0) {
      const Circle& capture = table.pockets[c.pocket];
      return (p - capture.centre_m).norm() - capture.radius_m;
    }
    if (c.jaw >= 0) {
      const JawArc& arc = table.jaws[c.jaw];
      const Eigen::Vector2d d = p - arc.centre_m;
      // The direction of the centre from the arc's centre, counterclockwise from the arc's start,
      // in [0, 2 pi).
      double turn = std::atan2(d.y(), d.x()) - arc.start_angle_rad;
      turn -= 2 * M_PI * std::floor(turn / (2 * M_PI));
      const double span = arc.end_angle_rad - arc.start_angle_rad;
      if (turn > span) return kInf;
      return d.norm() - (arc.radius_m + R);
    }
    const CushionSegment& s = table.cushions[c.cushion];
    const Eigen::Vector2d along = s.end_m - s.start_m;
    const double fraction = (p - s.start_m).dot(along) / along.squaredNorm();
    if (fraction < 0 || fraction > 1) return kInf;
    return s.inward_normal.dot(p - s.start_m) - R;
  }

  // Every ball `dt_s` after `start`, each on its own.
  std::vector<BallState> at(const std::vector<BallState>& start, double dt_s) const {
    std::vector<BallState> out(start.size());
    for (std::size_t i = 0; i < start.size(); ++i)
      out[i] = physics::advance(params.cloth, start[i], dt_s);
    return out;
  }

  double gapAt(const Contact& c, const std::vector<BallState>& start, double dt_s) const {
    return gap(c, at(start, dt_s));
  }

  // The contacts among the balls still on the table.
  std::vector<Contact> contacts(const std::vector<bool>& pocketed) const {
    const int n = static_cast<int>(pocketed.size());
    std::vector<Contact> out;
    for (int i = 0; i < n; ++i) {
      if (pocketed[i]) continue;
      for (int j = i + 1; j < n; ++j) {
        if (!pocketed[j]) out.push_back({i, j});
      }
      for (int k = 0; k < static_cast<int>(table.cushions.size()); ++k) out.push_back({i, -1, k});
      for (int k = 0; k < static_cast<int>(table.jaws.size()); ++k) out.push_back({i, -1, -1, k});
      for (int k = 0; k < static_cast<int>(table.pockets.size()); ++k) {
        out.push_back({i, -1, -1, -1, k});
      }
    }
    return out;
  }

  // The first time in (lo, hi] at which the gap is <= threshold, given gap(lo) > threshold and
  // gap(hi) <= threshold.
  double firstBelow(const Contact& c, const std::vector<BallState>& start, double lo, double hi,
                    double threshold) const {
    for (int it = 0; it < kBisectionIterations; ++it) {
      const double mid = 0.5 * (lo + hi);
      (gapAt(c, start, mid) <= threshold ? hi : lo) = mid;
    }
    return hi;
  }

  // The time of the least gap in [lo, hi] (a golden-section search; the gap is unimodal there).
  double leastGapTime(const Contact& c, const std::vector<BallState>& start, double lo,
                      double hi) const {
    const double ratio = 0.5 * (std::sqrt(5.0) - 1);
    double a = hi - ratio * (hi - lo), b = lo + ratio * (hi - lo);
    double ga = gapAt(c, start, a), gb = gapAt(c, start, b);
    for (int it = 0; it < kGoldenIterations; ++it) {
      if (ga < gb) {
        hi = b, b = a, gb = ga;
        a = hi - ratio * (hi - lo), ga = gapAt(c, start, a);
      } else {
        lo = a, a = b, ga = gb;
        b = lo + ratio * (hi - lo), gb = gapAt(c, start, b);
      }
    }
    return 0.5 * (lo + hi);
  }

  struct Scan {
    double first_touch_s = kInf;        // the first gap <= +kTouchTolerance_m (from the start)
    double first_penetration_s = kInf;  // the first gap < -kPenetrationTolerance_m
  };

  // Samples every contact from `start` up to `until_s` (times from the start). A contact already
  // touching at the start is only counted once it penetrates: it may be separating (a pair just
  // resolved, or frozen balls parting).
  Scan scan(const std::vector<BallState>& start, const std::vector<bool>& pocketed, double until_s,
            double step_s) const {
    const std::vector<Contact> all = contacts(pocketed);
    const int m = static_cast<int>(all.size());
    std::vector<double> g0(m), g1(m, kInf), g2(m, kInf);  // gaps now, one and two samples ago
    std::vector<bool> touching_at_start(m);
    const std::vector<BallState> initial = at(start, 0);
    for (int c = 0; c < m; ++c) {
      g1[c] = gap(all[c], initial);
      touching_at_start[c] = g1[c] <= kTouchTolerance_m;
    }
    Scan found;
    auto record = [&](int c, double lo, double hi, double g_lo, double g_hi) {
      // The crossing or dip of contact c inside [lo, hi]: refine both thresholds.
      const double thresholds[2] = {
          touching_at_start[c] ? -kPenetrationTolerance_m : kTouchTolerance_m,
          -kPenetrationTolerance_m};
      double* results[2] = {&found.first_touch_s, &found.first_penetration_s};
      double least_time = -1, least = kInf;
      for (int k = 0; k < 2; ++k) {
        const double threshold = k == 1 ? thresholds[1] : thresholds[0];
        if (lo >= *results[k]) continue;
        if (g_lo <= threshold) continue;  // counted at an earlier sample
        double t = kInf;
        if (g_hi <= threshold) {
          t = firstBelow(all[c], start, lo, hi, threshold);
        } else {
          if (least_time < 0) {
            least_time = leastGapTime(all[c], start, lo, hi);
            least = gapAt(all[c], start, least_time);
          }
          if (least <= threshold) t = firstBelow(all[c], start, lo, least_time, threshold);
        }
        *results[k] = std::min(*results[k], t);
      }
    };
    double t_prev2 = -step_s, t_prev = 0;
    for (int k = 1;; ++k) {
      const double t = std::min(k * step_s, until_s);
      const std::vector<BallState> now = at(start, t);
      for (int c = 0; c < m; ++c) {
        g0[c] = gap(all[c], now);
        if (!std::isfinite(g0[c]) || !std::isfinite(g1[c])) continue;
        const double touch = touching_at_start[c] ? -kPenetrationTolerance_m : kTouchTolerance_m;
        if (g0[c] <= touch) {
          record(c, t_prev, t, g1[c], g0[c]);
        } else if (std::isfinite(g2[c]) && g1[c] < g2[c] && g1[c] <= g0[c] &&
                   g1[c] <= touch + 2 * kSpeedBound_mps * step_s) {
          record(c, t_prev2, t, g2[c], g0[c]);  // a dip between samples
        }
      }
      std::swap(g2, g1);
      std::swap(g1, g0);
      t_prev2 = t_prev, t_prev = t;
      if (t >= until_s) break;
    }
    return found;
  }

  // Contact events checked, by kind.
  struct Checked {
    int total = 0, jaws = 0, pockets = 0;
  };

  // Checks a whole shot event by event; returns the contact events checked.
  Checked checkShot(const std::vector<BallState>& input, double step_s,
                    const std::string& scene) const {
    const SimulationResult result = simulate(params, table, input);
    const int n = static_cast<int>(input.size());
    std::vector<bool> pocketed(n, false);
    std::vector<BallState> known = input;  // each ball's last known state ...
    std::vector<double> known_time(n, 0);  // ... and its time
    std::vector<BallState> start = input;
    double start_time = 0;
    Checked checked;
    auto statesAt = [&](double t) {
      std::vector<BallState> out(n);
      for (int i = 0; i < n; ++i)
        out[i] = physics::advance(params.cloth, known[i], t - known_time[i]);
      return out;
    };
    for (const Event& e : result.events) {
      if (e.time_s > kCheckedSpan_s) break;
      const bool contact = e.kind != EventKind::StateChange;
      if (contact) {
        const double next = e.time_s - start_time;
        const Scan s = scan(start, pocketed, next + step_s, step_s);
        EXPECT_GE(s.first_penetration_s, next - step_s)
            << scene
            << ": the brute force sees an overlap at t = " << start_time + s.first_penetration_s
            << " s, before the loop's next contact (" << eventKindName(e.kind) << " at " << e.time_s
            << " s)";
        Contact own{e.ball};
        if (e.kind == EventKind::BallBall) own.other = e.other;
        if (e.kind == EventKind::Cushion) own.cushion = e.index;
        if (e.kind == EventKind::Jaw) own.jaw = e.index;
        if (e.kind == EventKind::Pocket) own.pocket = e.index;
        // A contact touching already at the start (a tangent one, or one closing by a hair) need
        // not penetrate to be real; it is checked to be touching at the event below.
        const bool own_touching_at_start = std::abs(gap(own, start)) <= kTouchTolerance_m;
        EXPECT_TRUE(s.first_touch_s <= next + step_s || own_touching_at_start)
            << scene << ": the brute force sees no contact near the loop's "
            << eventKindName(e.kind) << " at " << e.time_s << " s";
        const double own_gap = gap(own, statesAt(e.time_s));
        EXPECT_LE(std::abs(own_gap), kTouchTolerance_m)
            << scene << ": the loop's " << eventKindName(e.kind) << " at " << e.time_s
            << " s has gap " << own_gap;
        ++checked.total;
        checked.jaws += e.kind == EventKind::Jaw;
        checked.pockets += e.kind == EventKind::Pocket;
      }
      // Every ball's state at the event: the involved balls from the loop, the rest in closed form.
      const std::vector<BallState> now = statesAt(e.time_s);
      for (int i = 0; i < n; ++i) known[i] = now[i], known_time[i] = e.time_s;
      known[e.ball] = e.after[0];
      if (e.kind == EventKind::BallBall) known[e.other] = e.after[1];
      if (e.kind == EventKind::Pocket) pocketed[e.ball] = true;
      if (contact) start = known, start_time = e.time_s;
    }
    // After the last checked contact: no penetration within the checked span while balls move.
    const double last = std::min(kCheckedSpan_s, result.end_time_s);
    if (last > start_time) {
      const Scan s = scan(start, pocketed, last - start_time, step_s);
      EXPECT_EQ(s.first_penetration_s, kInf)
          << scene
          << ": the brute force sees an overlap at t = " << start_time + s.first_penetration_s
          << " s that the loop never reported";
    }
    return checked;
  }
};

class SceneMaker {
 public:
  explicit SceneMaker(std::uint64_t seed) : engine_(seed) {}
  double uniform(double lo, double hi) { return lo + (hi - lo) * ((engine_() >> 11) * 0x1.0p-53); }
  int index(int count) { return static_cast<int>(engine_() % static_cast<std::uint64_t>(count)); }

  // A ball at rest somewhere clear of the others and of the cushions (by `margin_m`), and outside
  // the capture circles `pockets` (it would start pocketed).
  bool placeClear(std::vector<BallState>* balls, double R, double margin_m,
                  const std::vector<Circle>& pockets = {}) {
    for (int attempt = 0; attempt < 1000; ++attempt) {
      BallState b;
      b.position = {uniform(-kTableLength_m / 2 + R + margin_m, kTableLength_m / 2 - R - margin_m),
                    uniform(-kTableWidth_m / 2 + R + margin_m, kTableWidth_m / 2 - R - margin_m)};
      bool clear = true;
      for (const BallState& o : *balls)
        clear = clear && (o.position - b.position).norm() > 2 * R + margin_m;
      for (const Circle& c : pockets)
        clear = clear && (c.centre_m - b.position).norm() > c.radius_m + margin_m;
      if (clear) {
        balls->push_back(b);
        return true;
      }
    }
    return false;
  }

  // A random strike: speed up to max_speed, spin up to spin_factor * speed / R on each axis.
  void strike(BallState* b, double R, double max_speed, double spin_factor) {
    const double speed = uniform(0, max_speed), angle = uniform(0, 2 * M_PI);
    b->velocity = {speed * std::cos(angle), speed * std::sin(angle), 0};
    const double w = spin_factor * speed / R;
    b->angular_velocity = {uniform(-w, w), uniform(-w, w), uniform(-w, w)};
  }

 private:
  std::mt19937_64 engine_;
};

// Random scenes: 2-4 balls, the cue ball struck at up to 4 m/s with random spin.
TEST(ShotSimulatorBruteForce, RandomScenesMissNoContact) {
  const Checker checker;
  const double R = checker.R;
  SceneMaker maker(20261121);
  int checked = 0;
  for (int scene = 0; scene < 200; ++scene) {
    std::vector<BallState> balls;
    const int n = 2 + scene % 3;
    for (int i = 0; i < n; ++i) ASSERT_TRUE(maker.placeClear(&balls, R, 1e-3));
    maker.strike(&balls[0], R, 4.0, 2.0);
    checked += checker.checkShot(balls, kStep_s, "random scene " + std::to_string(scene)).total;
  }
  EXPECT_GT(checked, 300) << "the scenes must exercise many contacts";
}

// The shipped 9 ft table, with pockets: cue balls sent at a pocket's mouth, off its centre by up to
// 1.5 times its half-width either way (into the opening, onto the jaw roundings and the facings),
// at up to 4 m/s with random spin, among 1-3 resting balls; jaw roundings, facings and capture
// circles are checked like cushions and balls.
TEST(ShotSimulatorBruteForce, ShotsAtThePocketsMissNoJawOrPocket) {
  const Table pool = builtinTable("pool-9ft");
  const Checker checker(geometryOf(pool));
  const double R = checker.R;
  SceneMaker maker(20261122);
  Checker::Checked checked;
  for (int scene = 0; scene < 150; ++scene) {
    std::vector<BallState> balls;
    const int n = 2 + scene % 3;
    for (int i = 0; i < n; ++i)
      ASSERT_TRUE(maker.placeClear(&balls, R, 1e-3, checker.table.pockets));
    const Pocket& pocket = pool.pockets[maker.index(static_cast<int>(pool.pockets.size()))];
    const Eigen::Vector2d across(-pocket.axis.y(), pocket.axis.x());
    const double half_mouth = 0.5 * (pocket.jaw_tips_m[1] - pocket.jaw_tips_m[0]).norm();
    const Eigen::Vector2d target =
        pocket.mouth_centre_m + maker.uniform(-1.5, 1.5) * half_mouth * across;
    maker.strike(&balls[0], R, 4.0, 2.0);
    const Eigen::Vector2d aim = (target - balls[0].position).normalized();
    const double speed = maker.uniform(0.5, 4.0);
    balls[0].velocity = {speed * aim.x(), speed * aim.y(), 0};
    const Checker::Checked c =
        checker.checkShot(balls, kStep_s, "pocket scene " + std::to_string(scene));
    checked.total += c.total, checked.jaws += c.jaws, checked.pockets += c.pockets;
  }
  // The seeded set checks 253 contacts, 19 at a jaw rounding and 27 pockets.
  EXPECT_GT(checked.jaws, 10) << "the scenes must exercise the jaw roundings";
  EXPECT_GT(checked.pockets, 15) << "the scenes must exercise the capture circles";
  EXPECT_GT(checked.total, 200);
}

// A ball rolling or stunned straight past another at a centre distance of 2R + offset: the loop
// must report the contact for a real overlap (offset -1e-8 m and beyond) and none for a clear
// pass (+1e-8 m and beyond); in between either is right, but a reported one must be touching.
TEST(ShotSimulatorBruteForce, GrazingPassesAreDecidedByTheGap) {
  const Checker checker;
  const double R = checker.R;
  SceneMaker maker(7);
  const double offsets_m[] = {-1e-4, -1e-6, -1e-8, -1e-12, 0, 1e-12, 1e-8, 1e-6, 1e-4};
  for (int scene = 0; scene < 90; ++scene) {
    const double offset = offsets_m[scene % 9];
    const double angle = maker.uniform(0, 2 * M_PI), speed = maker.uniform(1, 4);
    const Eigen::Vector2d dir(std::cos(angle), std::sin(angle)), side(-dir.y(), dir.x());
    std::vector<BallState> balls(2);
    balls[0].position = -0.3 * dir;
    balls[0].velocity = {speed * dir.x(), speed * dir.y(), 0};
    // Follow (rolling or more) about the axis across the path, and spin about z: the path stays
    // straight and the ball reaches the other one.
    const double across = maker.uniform(1, 2) * speed / R;
    balls[0].angular_velocity = {across * side.x(), across * side.y(),
                                 maker.uniform(-2, 2) * speed / R};
    balls[1].position = 0.2 * dir + (2 * R + offset) * side;
    const std::string name =
        "grazing scene " + std::to_string(scene) + " (offset " + std::to_string(offset) + " m)";
    checker.checkShot(balls, kStep_s, name);
    const SimulationResult r = simulate(checker.params, checker.table, balls);
    bool hit = false;  // on the first pass, before any cushion
    for (const Event& e : r.events) {
      if (e.kind == EventKind::Cushion) break;
      hit = hit || e.kind == EventKind::BallBall;
    }
    if (offset <= -1e-8) {
      EXPECT_TRUE(hit) << name;
    }
    if (offset >= 1e-8) {
      EXPECT_FALSE(hit) << name;
    }
  }
}

// A ball rolling along a cushion at R + offset from its line, or angled into it by a hair.
TEST(ShotSimulatorBruteForce, BallsRunningAlongACushionAreDecidedByTheGap) {
  const Checker checker;
  const double R = checker.R;
  SceneMaker maker(11);
  const double offsets_m[] = {0, 1e-12, 1e-8, 1e-6};
  const double slopes[] = {0, -1e-9, -1e-6, 1e-6};  // vy / vx; negative goes into cushion 0
  for (int scene = 0; scene < 64; ++scene) {
    const double offset = offsets_m[scene % 4], slope = slopes[(scene / 4) % 4];
    const double speed = maker.uniform(0.1, 3);
    std::vector<BallState> balls(1);
    balls[0].position = {-0.5, -kTableWidth_m / 2 + R + offset};
    balls[0].velocity = {speed, speed * slope, 0};
    balls[0].angular_velocity = {-speed * slope / R, speed / R, maker.uniform(-30, 30)};  // rolling
    checker.checkShot(balls, kStep_s,
                      "cushion-run scene " + std::to_string(scene) + " (offset " +
                          std::to_string(offset) + " m, slope " + std::to_string(slope) + ")");
  }
}

// Frozen balls: two touching balls, one moving away from, toward or along the other; and a third
// ball struck at a frozen pair or triangle.
TEST(ShotSimulatorBruteForce, FrozenBallsPartingOrPushedMissNoContact) {
  const Checker checker;
  const double R = checker.R;
  SceneMaker maker(13);
  int checked = 0;
  for (int scene = 0; scene < 90; ++scene) {
    const double angle = maker.uniform(0, 2 * M_PI);
    const Eigen::Vector2d dir(std::cos(angle), std::sin(angle)), side(-dir.y(), dir.x());
    std::vector<BallState> balls(2);
    balls[0].position = Eigen::Vector2d(maker.uniform(-0.5, 0.5), maker.uniform(-0.2, 0.2));
    balls[1].position = balls[0].position + 2 * R * dir;
    const int kind = scene % 5;
    const double speed = maker.uniform(1e-3, 3);
    Eigen::Vector2d v;
    if (kind == 0)
      v = -dir;  // away
    else if (kind == 1)
      v = dir;  // toward
    else if (kind == 2)
      v = side;  // along the tangent
    else
      v = (maker.uniform(-1, 1) * dir + maker.uniform(-1, 1) * side);  // anything
    if (v.norm() > 0) v.normalize();
    if (kind < 4) {
      balls[0].velocity = {speed * v.x(), speed * v.y(), 0};
      const double w = 2 * speed / R;
      balls[0].angular_velocity = {maker.uniform(-w, w), maker.uniform(-w, w),
                                   maker.uniform(-w, w)};
    } else {
      // A cue ball aimed at the pair (or the pair plus a third ball in a triangle).
      if (scene % 2 == 0) balls.push_back(BallState{});
      if (balls.size() == 3)
        balls[2].position = balls[0].position + 2 * R * (0.5 * dir + std::sqrt(0.75) * side);
      BallState cue;
      cue.position = balls[0].position - 0.4 * dir + maker.uniform(-R, R) * side;
      const Eigen::Vector2d aim = (balls[0].position - cue.position).normalized();
      cue.velocity = {speed * aim.x(), speed * aim.y(), 0};
      cue.angular_velocity = {maker.uniform(-50, 50), maker.uniform(-50, 50),
                              maker.uniform(-50, 50)};
      balls.push_back(cue);
    }
    checked += checker.checkShot(balls, kStep_s, "frozen scene " + std::to_string(scene)).total;
  }
  EXPECT_GT(checked, 60);
}

// The refined step: the same random scenes' first checks with a ten times smaller step.
TEST(ShotSimulatorBruteForce, RefinedStepAgrees) {
  const Checker checker;
  const double R = checker.R;
  SceneMaker maker(20261121);
  for (int scene = 0; scene < 10; ++scene) {
    std::vector<BallState> balls;
    const int n = 2 + scene % 3;
    for (int i = 0; i < n; ++i) ASSERT_TRUE(maker.placeClear(&balls, R, 1e-3));
    maker.strike(&balls[0], R, 4.0, 2.0);
    checker.checkShot(balls, kFineStep_s, "random scene " + std::to_string(scene) + " (fine step)");
  }
}

}  // namespace
}  // namespace baize::engine
