#include "engine/play/stress_shots.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <stdexcept>

#include "physics/cue_strike.h"

namespace baize::engine {
namespace {

using physics::BallState;

// The strongest ball speed of the state shots, m/s: above any cue strike (a break is about
// 10 m/s).
constexpr double kMaxSpeed_mps = 16.0;
// The most spin on each axis of the state shots, in units of speed / R: beyond what a cue tip can
// give (about 2.5).
constexpr double kMaxSpinFactor = 3.0;
// Tiny state shots: speeds log-uniform in this range, m/s, around the stopping thresholds' scale.
constexpr double kTinySpeedMin_mps = 1e-6;
constexpr double kTinySpeedMax_mps = 1e-3;
// Tiny cue shots: cue speeds log-uniform in this range, m/s (the ball stops within 0.1 um to a few
// cm; speed_mps must be > 0).
constexpr double kTinyCueSpeedMin_mps = 1e-5;
constexpr double kTinyCueSpeedMax_mps = 0.1;
// The steepest cue of the cue shots, deg: a masse cue stands at 70-80 deg.
constexpr double kMaxElevation_deg = 80.0;
// Tip offsets at "the miscue limit" sit this fraction inside it, so that rounding of a^2 + b^2
// never makes a legal offset a miscue.
constexpr double kMiscueMargin = 1e-12;
// Touching balls and cushions are placed exactly; rounding may leave them overlapping by about
// 1e-16 m, which placement checks forgive up to this, m (simulate() forgives 1e-9 m).
constexpr double kTouchSlack_m = 1e-12;
// Near-simultaneous arrivals: the second ball arrives this much later or earlier, s (log-uniform),
// when not at exactly the same computed instant; 1e-12 s is a few ulps of the arrival time.
constexpr double kArrivalOffsetMin_s = 1e-12;
constexpr double kArrivalOffsetMax_s = 1e-3;
// A rail with an end within this distance of a pocket's mouth centre is "beside the pocket", m:
// the mouth's half width plus about two ball diameters.
constexpr double kBesidePocket_m = 0.15;
// How often a generator tries a random placement before it settles for fewer balls.
constexpr int kPlacementAttempts = 200;

struct CuePlan;

// Where a cue shot's balls stand (places[0] the cue ball) and the heading it is aimed at, deg.
struct CueLayout {
  std::vector<Eigen::Vector2d> places;
  double aim_deg = 0;
  void aimAt(const Eigen::Vector2d& target, double cut_R, double R);
};

class ShotMaker {
 public:
  ShotMaker(std::uint64_t seed, const StressTables& tables) : engine_(seed), tables_(tables) {}

  double uniform(double lo, double hi) { return lo + (hi - lo) * ((engine_() >> 11) * 0x1.0p-53); }
  double logUniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
  int integer(int lo, int hi) {
    return lo + static_cast<int>(engine_() % static_cast<std::uint64_t>(hi - lo + 1));
  }
  bool chance(int one_in) { return integer(1, one_in) == 1; }
  Eigen::Vector2d direction() {
    const double a = uniform(0, 2 * M_PI);
    return {std::cos(a), std::sin(a)};
  }

  // Whether a ball may stand at p on table t: on the table (touching allowed), not in a pocket,
  // not overlapping `balls`, and within the rectangle a scene accepts when `scene` is set.
  bool clear(const StressTable& t, const std::vector<Eigen::Vector2d>& balls,
             const Eigen::Vector2d& p, bool scene) const {
    const double R = t.params.ball.radius_m;
    if (scene &&
        (std::abs(p.x()) > t.table.length_m / 2 - R || std::abs(p.y()) > t.table.width_m / 2 - R)) {
      return false;
    }
    if (!offTableReason(t, p, kTouchSlack_m).empty() || inPocket(t, p)) return false;
    for (const Eigen::Vector2d& o : balls) {
      if ((o - p).norm() < 2 * R - kTouchSlack_m) return false;
    }
    return true;
  }

  Eigen::Vector2d anywhere(const StressTable& t) {
    const double R = t.params.ball.radius_m;
    return {uniform(-t.table.length_m / 2 + R, t.table.length_m / 2 - R),
            uniform(-t.table.width_m / 2 + R, t.table.width_m / 2 - R)};
  }

  // Adds balls at random clear places until there are `count` (gives up quietly on a full table).
  void fill(const StressTable& t, std::vector<Eigen::Vector2d>* balls, int count, bool scene) {
    for (int attempt = 0; attempt < kPlacementAttempts && static_cast<int>(balls->size()) < count;
         ++attempt) {
      const Eigen::Vector2d p = anywhere(t);
      if (clear(t, *balls, p, scene)) balls->push_back(p);
    }
  }

  // Velocity `speed` along `dir` and spin up to kMaxSpinFactor * speed / R on each axis.
  BallState struck(const Eigen::Vector2d& at, const Eigen::Vector2d& dir, double speed, double R) {
    BallState b;
    b.position = at;
    b.velocity = {speed * dir.x(), speed * dir.y(), 0};
    const double w = kMaxSpinFactor * speed / R;
    b.angular_velocity = {uniform(-w, w), uniform(-w, w), uniform(-w, w)};
    return b;
  }

  StressShot make(StressShotKind kind, int max_balls);

 private:
  StressShot rectangleShot(StressShotKind kind, int max_balls);
  StressShot nearSimultaneous(int max_balls);
  StressShot inTheMouth(int max_balls);
  StressShot cueShot(StressShotKind kind, int max_balls);
  void layOutAtPocket(const StressTable& t, int max_balls, CueLayout* layout);
  void layOutRack(const StressTable& t, CueLayout* layout);
  void layOutClump(const StressTable& t, int max_balls, CueLayout* layout);
  void layOutTiny(const StressTable& t, int max_balls, CueLayout* layout);
  CuePlan drawStrike(StressShotKind kind, double aim_deg,
                     const physics::CueStrikeParams& cue_params);
  static double ballRadius(const StressTable& t) { return t.params.ball.radius_m; }
  // A place touching a rail, facing or jaw of pocket k (clear of `balls`), if one is found.
  std::optional<Eigen::Vector2d> againstPocket(const StressTable& t, int pocket,
                                               const std::vector<Eigen::Vector2d>& balls,
                                               bool scene);

  std::mt19937_64 engine_;
  const StressTables& tables_;
};

std::vector<BallState> atRest(const std::vector<Eigen::Vector2d>& places) {
  std::vector<BallState> balls(places.size());
  for (std::size_t i = 0; i < places.size(); ++i) balls[i].position = places[i];
  return balls;
}

StressShot ShotMaker::rectangleShot(StressShotKind kind, int max_balls) {
  const StressTable& t = tables_.of(StressTableId::Rectangle);
  const double R = t.params.ball.radius_m;
  StressShot shot;
  shot.kind = kind;
  shot.table = t.id;
  const double speed = uniform(0, kMaxSpeed_mps);
  const Eigen::Vector2d centre(uniform(-0.8, 0.8), uniform(-0.3, 0.3));
  const Eigen::Vector2d dir = direction(), side(-dir.y(), dir.x());
  std::vector<Eigen::Vector2d> places;
  // A cue ball `distance` back from `target` along -aim, struck along aim; added if clear.
  auto addCue = [&](const Eigen::Vector2d& target, const Eigen::Vector2d& aim, double distance) {
    const Eigen::Vector2d at = target - distance * aim;
    std::vector<BallState> balls = atRest(places);
    if (clear(t, places, at, false)) {
      places.push_back(at);
      balls.push_back(struck(at, aim, speed, R));
    }
    return balls;
  };
  switch (kind) {
    case StressShotKind::GapShot: {  // at the gap between two touching balls: two contacts at once
      places = {centre + R * side, centre - R * side};
      shot.balls = addCue(centre, dir, uniform(0.1, 0.3));
      break;
    }
    case StressShotKind::FrozenLine: {  // a row of touching balls, the cue along or across it
      const int row = std::max(2, std::min(max_balls - 1, 4));
      for (int i = 0; i < row; ++i) places.push_back(centre + (2 * R * i) * dir);
      const Eigen::Vector2d aim =
          integer(0, 1) ? dir : Eigen::Vector2d((dir + uniform(-0.3, 0.3) * side).normalized());
      shot.balls = addCue(centre, aim, uniform(0.1, 0.3));
      break;
    }
    case StressShotKind::FrozenTriangle: {  // three mutually touching balls
      places = {centre, centre + 2 * R * dir,
                centre + 2 * R * (0.5 * dir + std::sqrt(0.75) * side)};
      const Eigen::Vector2d aim = (dir + uniform(-0.2, 0.2) * side).normalized();
      shot.balls = addCue(centre, aim, uniform(0.1, 0.3));
      const std::size_t before = places.size();
      fill(t, &places, std::min(max_balls, static_cast<int>(places.size()) + integer(0, 1)), false);
      for (std::size_t i = before; i < places.size(); ++i)
        shot.balls.push_back(atRest({places[i]})[0]);
      break;
    }
    case StressShotKind::CushionFrozen: {  // a ball touching cushion 0 (y = -W/2), hit or moving
      const Eigen::Vector2d a(uniform(-1.0, 1.0), -t.table.width_m / 2 + R);
      places = {a};
      if (integer(0, 1)) {
        shot.balls = {struck(a, direction(), speed, R)};
      } else {
        const Eigen::Vector2d aim = Eigen::Vector2d(uniform(-1, 1), -1).normalized();
        shot.balls = addCue(a, aim, uniform(0.1, 0.4));
      }
      const std::size_t before = places.size();
      fill(t, &places, std::min(max_balls, static_cast<int>(places.size()) + integer(0, 2)), false);
      for (std::size_t i = before; i < places.size(); ++i)
        shot.balls.push_back(atRest({places[i]})[0]);
      break;
    }
    case StressShotKind::Tiny: {  // speeds near the stopping thresholds, often at a touching ball
      places = {centre, centre + 2 * R * dir};
      fill(t, &places, std::min(max_balls, 2 + integer(0, 1)), false);
      shot.balls = atRest(places);
      const Eigen::Vector2d heading = integer(0, 1) ? dir : direction();
      shot.balls[0] = struck(centre, heading, logUniform(kTinySpeedMin_mps, kTinySpeedMax_mps), R);
      break;
    }
    case StressShotKind::Grazing: {  // a straight pass at 2R + a tiny offset of either sign
      const double offset =
          (integer(0, 1) ? 1 : -1) * logUniform(1e-16, 1e-6) * (integer(0, 4) ? 1 : 0);
      places = {centre};
      const Eigen::Vector2d at = centre - uniform(0.1, 0.5) * dir - (2 * R + offset) * side;
      shot.balls = atRest(places);
      if (clear(t, places, at, false)) {
        places.push_back(at);
        BallState cue;
        cue.position = at;
        cue.velocity = {speed * dir.x(), speed * dir.y(), 0};
        const double follow = uniform(0, kMaxSpinFactor) * speed / R;  // about the axis across
        cue.angular_velocity = {follow * side.x(), follow * side.y(),
                                uniform(-kMaxSpinFactor, kMaxSpinFactor) * speed / R};
        shot.balls.push_back(cue);
      }
      const std::size_t before = places.size();
      fill(t, &places, std::min(max_balls, 2 + integer(0, 1)), false);
      for (std::size_t i = before; i < places.size(); ++i)
        shot.balls.push_back(atRest({places[i]})[0]);
      break;
    }
    default: {  // Random: 1 to max_balls anywhere, the first struck
      fill(t, &places, integer(1, max_balls), false);
      shot.balls = atRest(places);
      shot.balls[0] = struck(places[0], direction(), speed, R);
      break;
    }
  }
  return shot;
}

// Two balls rolling at a third from directions at least 60 deg apart (so that they meet it, not
// each other, first), timed to arrive at the same computed instant or a tiny offset apart. A
// rolling ball slows at mu_r g, so reaching distance s at time t takes v = s / t + mu_r g t / 2.
StressShot ShotMaker::nearSimultaneous(int max_balls) {
  const StressTable& t = tables_.of(StressTableId::Pool9ft);
  const double R = t.params.ball.radius_m;
  const double a = t.params.cloth.rolling_friction * t.params.cloth.gravity_mps2;
  StressShot shot;
  shot.kind = StressShotKind::NearSimultaneous;
  shot.table = t.id;
  // The target well inside the table (m), so that both approaches fit.
  const Eigen::Vector2d target(uniform(-0.6, 0.6), uniform(-0.2, 0.2));
  std::vector<Eigen::Vector2d> places = {target};
  shot.balls = atRest(places);
  const double arrival_s = uniform(0.05, 1.0);  // when they arrive, s
  const double first = uniform(0, 2 * M_PI);
  const double second = first + (integer(0, 3) ? uniform(M_PI / 3, M_PI) : M_PI / 3);
  for (int k = 0; k < 2; ++k) {
    const double angle = k == 0 ? first : second;
    const Eigen::Vector2d from(std::cos(angle), std::sin(angle)), across(-from.y(), from.x());
    // The offset of the path from the target's centre (0: head on), below 2R so it touches.
    const double impact = integer(0, 2) ? 0 : uniform(-1.9, 1.9) * R;
    const double distance = uniform(0.05, 0.5) + 2 * R;  // centre to centre, m
    const Eigen::Vector2d at = target + distance * from + impact * across;
    if (!clear(t, places, at, false)) continue;
    const double travel_m = distance - std::sqrt(4 * R * R - impact * impact);
    double when_s = arrival_s;
    if (k == 1 && integer(0, 2)) {
      when_s += (integer(0, 1) ? 1 : -1) * logUniform(kArrivalOffsetMin_s, kArrivalOffsetMax_s);
    }
    const double speed = travel_m / when_s + a * when_s / 2;
    BallState b;
    b.position = at;
    b.velocity = {-speed * from.x(), -speed * from.y(), 0};
    // Rolling: w_xy = z x v / R.
    b.angular_velocity = {-b.velocity.y() / R, b.velocity.x() / R, 0};
    places.push_back(at);
    shot.balls.push_back(b);
  }
  const std::size_t before = places.size();
  fill(t, &places, std::min(max_balls, static_cast<int>(places.size()) + integer(0, 2)), false);
  for (std::size_t i = before; i < places.size(); ++i) shot.balls.push_back(atRest({places[i]})[0]);
  return shot;
}

std::optional<Eigen::Vector2d> ShotMaker::againstPocket(const StressTable& t, int pocket,
                                                        const std::vector<Eigen::Vector2d>& balls,
                                                        bool scene) {
  const double R = t.params.ball.radius_m;
  for (int attempt = 0; attempt < kPlacementAttempts; ++attempt) {
    Eigen::Vector2d p;
    const int where = integer(0, 2);
    if (where == 0) {  // touching a straight nose of the pocket (a facing, or a rail near it)
      std::vector<const engine::CushionSegment*> near;
      for (const engine::CushionSegment& c : t.geometry.cushions) {
        const double reach = std::min((c.start_m - t.table.pockets[pocket].mouth_centre_m).norm(),
                                      (c.end_m - t.table.pockets[pocket].mouth_centre_m).norm());
        if (c.pocket == pocket || reach < kBesidePocket_m) near.push_back(&c);
      }
      const engine::CushionSegment& c = *near[integer(0, static_cast<int>(near.size()) - 1)];
      const double s = uniform(0, 1);  // where along the nose
      p = c.start_m + s * (c.end_m - c.start_m) + R * c.inward_normal;
    } else if (where == 1) {  // touching a jaw's rounding
      const engine::JawArc& jaw = t.geometry.jaws[2 * pocket + integer(0, 1)];
      const double angle = uniform(jaw.start_angle_rad, jaw.end_angle_rad);
      p = jaw.centre_m + (jaw.radius_m + R) * Eigen::Vector2d(std::cos(angle), std::sin(angle));
    } else {  // anywhere in the mouth and throat
      const engine::Pocket& k = t.table.pockets[pocket];
      const Eigen::Vector2d across(-k.axis.y(), k.axis.x());
      const double half = (k.jaw_tips_m[0] - k.jaw_tips_m[1]).norm() / 2;
      p = k.mouth_centre_m + uniform(-2 * R, k.capture.radius_m) * k.axis +
          uniform(-half, half) * across;
    }
    if (clear(t, balls, p, scene)) return p;
  }
  return std::nullopt;
}

// A ball in a pocket's mouth, against a jaw or facing or a rail beside the pocket: either moving
// itself (any speed, tiny ones included, any spin) or at rest and hit by a ball from the table.
StressShot ShotMaker::inTheMouth(int max_balls) {
  const StressTable& t =
      tables_.of(chance(3) ? StressTableId::Snooker12ft : StressTableId::Pool9ft);
  const double R = t.params.ball.radius_m;
  StressShot shot;
  shot.kind = StressShotKind::InTheMouth;
  shot.table = t.id;
  const int pocket = integer(0, static_cast<int>(t.table.pockets.size()) - 1);
  std::vector<Eigen::Vector2d> places;
  if (const auto p = againstPocket(t, pocket, places, false)) places.push_back(*p);
  fill(t, &places, std::min(max_balls, static_cast<int>(places.size()) + integer(0, 2)), false);
  shot.balls = atRest(places);
  if (places.empty()) return shot;
  const double speed =
      chance(3) ? logUniform(kTinySpeedMin_mps, kTinySpeedMax_mps) : uniform(0, kMaxSpeed_mps);
  if (integer(0, 1)) {
    shot.balls[0] = struck(places[0], direction(), speed, R);
  } else {  // hit by a ball coming out of the table at it
    const Eigen::Vector2d to_table = (-places[0]).normalized();
    const Eigen::Vector2d aim =
        -(to_table + uniform(-0.5, 0.5) * Eigen::Vector2d(-to_table.y(), to_table.x()))
             .normalized();
    const Eigen::Vector2d at = places[0] - uniform(2.05 * R, 0.4) * aim;
    if (clear(t, places, at, false)) {
      places.push_back(at);
      shot.balls.push_back(struck(at, aim, speed, R));
    }
  }
  return shot;
}

struct CuePlan {
  std::map<std::string, Eigen::Vector2d> positions;  // by ball id; "cue" is struck
  physics::CueShot shot;                             // heading and elevation unused
  double heading_deg = 0;
  double elevation_deg = 0;
};

// Aims the cue ball (places[0]) so that its line passes cut_R * R from the target's centre
// (|cut_R| < 2 hits it: 0 full, near 2 thin).
void CueLayout::aimAt(const Eigen::Vector2d& target, double cut_R, double R) {
  const Eigen::Vector2d to = target - places[0];
  const double cut = std::asin(std::clamp(cut_R * R / std::max(to.norm(), 2 * R), -1.0, 1.0));
  aim_deg = (std::atan2(to.y(), to.x()) + cut) * 180 / M_PI;
}

// An object ball against a rail, facing or jaw; the cue ball at it.
void ShotMaker::layOutAtPocket(const StressTable& t, int max_balls, CueLayout* layout) {
  std::vector<Eigen::Vector2d>& places = layout->places;
  const int pocket = integer(0, static_cast<int>(t.table.pockets.size()) - 1);
  std::vector<Eigen::Vector2d> objects;
  if (const auto p = againstPocket(t, pocket, objects, true)) objects.push_back(*p);
  // The cue ball within 0.8 m of the object ball, or anywhere when that finds no room.
  for (int attempt = 0; attempt < kPlacementAttempts && places.empty(); ++attempt) {
    const Eigen::Vector2d at = objects.empty() || attempt >= kPlacementAttempts / 2
                                   ? anywhere(t)
                                   : Eigen::Vector2d(objects[0] + uniform(0.06, 0.8) * direction());
    if (clear(t, objects, at, true)) places.push_back(at);
  }
  if (places.empty()) {
    objects.clear();
    places.push_back(Eigen::Vector2d::Zero());
  }
  places.insert(places.end(), objects.begin(), objects.end());
  if (places.size() > 1) layout->aimAt(places[1], uniform(-1.5, 1.5), ballRadius(t));
  fill(t, &places, std::min(max_balls, static_cast<int>(places.size()) + integer(0, 2)), true);
}

// A rack, jittered as scenes jitter them, the cue ball anywhere in front.
void ShotMaker::layOutRack(const StressTable& t, CueLayout* layout) {
  std::vector<Eigen::Vector2d>& places = layout->places;
  engine::RackOptions options;
  options.jitter_seed = static_cast<std::uint64_t>(integer(0, 1 << 30));
  options.jitter_radius_m = chance(2) ? 0 : options.gap_m / 2;
  const std::string rack =
      t.id == StressTableId::Snooker12ft ? "snooker" : (chance(2) ? "9-ball" : "8-ball");
  for (const engine::PlacedBall& b : engine::placeRack(rack, t.table, t.ball_set, options)) {
    places.push_back(b.position_m);
  }
  // Rack order puts the cue ball first; move it somewhere clear at random.
  std::vector<Eigen::Vector2d> others(places.begin() + 1, places.end());
  for (int attempt = 0; attempt < kPlacementAttempts; ++attempt) {
    const Eigen::Vector2d at = anywhere(t);
    if (clear(t, others, at, true)) {
      places[0] = at;
      break;
    }
  }
  layout->aimAt(places[1 + integer(0, static_cast<int>(places.size()) - 2)], uniform(-1, 1),
                ballRadius(t));
}

// A clump: each ball touches (gap 0 or engine::kFrozenGap_m) one already placed; sometimes the
// first one touches a rail. The cue ball anywhere clear.
void ShotMaker::layOutClump(const StressTable& t, int max_balls, CueLayout* layout) {
  std::vector<Eigen::Vector2d>& places = layout->places;
  const double R = ballRadius(t);
  std::vector<Eigen::Vector2d> clump;
  Eigen::Vector2d first = anywhere(t);
  if (chance(2)) first.y() = (chance(2) ? 1 : -1) * (t.table.width_m / 2 - R);
  if (clear(t, clump, first, true)) clump.push_back(first);
  const int size = integer(2, std::max(2, max_balls - 1));
  for (int attempt = 0;
       attempt < kPlacementAttempts && !clump.empty() && static_cast<int>(clump.size()) < size;
       ++attempt) {
    const Eigen::Vector2d& next_to = clump[integer(0, static_cast<int>(clump.size()) - 1)];
    const double gap = chance(2) ? 0 : engine::kFrozenGap_m;
    const Eigen::Vector2d at = next_to + (2 * R + gap) * direction();
    if (clear(t, clump, at, true)) clump.push_back(at);
  }
  for (int attempt = 0; attempt < kPlacementAttempts && places.empty(); ++attempt) {
    const Eigen::Vector2d at = anywhere(t);
    if (clear(t, clump, at, true)) places.push_back(at);
  }
  if (places.empty()) {
    places.push_back(clump.back());
    clump.pop_back();
  }
  places.insert(places.end(), clump.begin(), clump.end());
  if (places.size() > 1)
    layout->aimAt(places[1 + integer(0, static_cast<int>(places.size()) - 2)], uniform(-1.2, 1.2),
                  R);
}

// The cue ball often touching a ball or a rail.
void ShotMaker::layOutTiny(const StressTable& t, int max_balls, CueLayout* layout) {
  std::vector<Eigen::Vector2d>& places = layout->places;
  const double R = ballRadius(t);
  fill(t, &places, 1, true);
  const Eigen::Vector2d at = places[0];
  const int touch = integer(0, 2);
  if (touch == 0) {
    const Eigen::Vector2d other = at + 2 * R * direction();
    if (clear(t, places, other, true)) places.push_back(other);
    if (places.size() > 1) layout->aimAt(places[1], uniform(-1.9, 1.9), R);
  } else if (touch == 1) {
    places[0].y() = (chance(2) ? 1 : -1) * (t.table.width_m / 2 - R);
    if (!clear(t, {}, places[0], true)) places[0] = at;
  }
  fill(t, &places, std::min(max_balls, static_cast<int>(places.size()) + integer(0, 2)), true);
}

// The strike: cue speed, elevation and a tip offset inside the miscue circle (a quarter of them on
// its edge); an offset the elevated cue cannot reach (Q . d >= 0) is drawn again.
CuePlan ShotMaker::drawStrike(StressShotKind kind, double aim_deg,
                              const physics::CueStrikeParams& cue_params) {
  CuePlan plan;
  plan.heading_deg = aim_deg;
  plan.elevation_deg = chance(3) ? 0 : uniform(0, kMaxElevation_deg);
  plan.shot.speed_mps = kind == StressShotKind::CueTiny
                            ? logUniform(kTinyCueSpeedMin_mps, kTinyCueSpeedMax_mps)
                            // Up to the fastest cue a scene may give, which sends the ball off
                            // at about the state shots' 16 m/s (physics/cue_strike.h).
                            : uniform(0.05, physics::kMaxCueSpeed_mps);
  for (int attempt = 0;; ++attempt) {
    const double radius = (chance(4) ? 1.0 : std::sqrt(uniform(0, 1))) *
                          physics::kMiscueOffsetLimit * (1 - kMiscueMargin);
    const double angle = uniform(0, 2 * M_PI);
    plan.shot.side_offset = radius * std::cos(angle);
    plan.shot.height_offset = radius * std::sin(angle);
    physics::CueShot trial = plan.shot;
    trial.heading_rad = plan.heading_deg * M_PI / 180;
    trial.elevation_rad = plan.elevation_deg * M_PI / 180;
    try {
      physics::strikeCueBall(cue_params, trial);
      break;
    } catch (const std::invalid_argument&) {
      if (attempt > 50) plan.elevation_deg = 0;  // a level cue reaches every legal offset
    }
  }
  return plan;
}

// The cue shot's scene file (as `baize stress --failures` writes it) and the scene exactly as
// engine::loadScene builds it from that file, struck: balls in the JSON object's key order,
// angles converted from degrees the same way.
void writeCueShot(const StressTable& t, CuePlan plan, const std::vector<Eigen::Vector2d>& places,
                  StressShot* shot) {
  std::vector<std::string> ids;
  for (const engine::BallSpec& b : t.ball_set.balls) ids.push_back(b.id);
  // "cue" first in the ball set; the others take the set's ids in order.
  for (std::size_t i = 0; i < places.size() && i < ids.size(); ++i)
    plan.positions[ids[i]] = places[i];

  nlohmann::json doc;
  doc["table"] = t.name;
  doc["ball_set"] = t.ball_set.name;
  doc["balls"] = nlohmann::json::object();
  for (const auto& [id, p] : plan.positions) doc["balls"][id] = {p.x(), p.y()};
  doc["shot"] = {{"speed_mps", plan.shot.speed_mps},
                 {"heading_deg", plan.heading_deg},
                 {"elevation_deg", plan.elevation_deg},
                 {"side", plan.shot.side_offset},
                 {"height", plan.shot.height_offset}};

  engine::Scene scene;
  scene.source = "stress";
  scene.table = t.table;
  scene.ball_set = t.ball_set;
  for (const auto& item : doc["balls"].items()) {
    scene.balls.push_back({item.key(), plan.positions.at(item.key())});
  }
  scene.cue_ball = "cue";
  scene.shot = plan.shot;
  scene.shot.heading_rad = plan.heading_deg * M_PI / 180;
  scene.shot.elevation_rad = plan.elevation_deg * M_PI / 180;
  shot->balls = engine::sceneStart(scene).balls;
  shot->scene = scene;
  shot->scene_json = doc;
}

StressShot ShotMaker::cueShot(StressShotKind kind, int max_balls) {
  const StressTable& t =
      tables_.of(chance(4) ? StressTableId::Snooker12ft : StressTableId::Pool9ft);
  StressShot shot;
  shot.kind = kind;
  shot.table = t.id;
  CueLayout layout;
  layout.aim_deg = uniform(-180, 180);  // the heading, unless aimed at a ball
  switch (kind) {
    case StressShotKind::CueAtPocket:
      layOutAtPocket(t, max_balls, &layout);
      break;
    case StressShotKind::CueCluster:
      if (chance(3))
        layOutRack(t, &layout);
      else
        layOutClump(t, max_balls, &layout);
      break;
    case StressShotKind::CueTiny:
      layOutTiny(t, max_balls, &layout);
      break;
    default:  // CueMasse: 1 to max_balls anywhere
      fill(t, &layout.places, integer(1, max_balls), true);
      if (layout.places.size() > 1 && chance(2))
        layout.aimAt(layout.places[1], uniform(-2, 2), ballRadius(t));
      break;
  }
  if (layout.places.empty()) layout.places.push_back(Eigen::Vector2d::Zero());
  engine::Scene bare;
  bare.table = t.table;
  bare.ball_set = t.ball_set;
  const physics::CueStrikeParams cue_params = engine::cueStrikeParamsFor(bare);
  const CuePlan plan = drawStrike(kind, layout.aim_deg, cue_params);
  writeCueShot(t, plan, layout.places, &shot);
  return shot;
}

StressShot ShotMaker::make(StressShotKind kind, int max_balls) {
  switch (kind) {
    case StressShotKind::NearSimultaneous:
      return nearSimultaneous(max_balls);
    case StressShotKind::InTheMouth:
      return inTheMouth(max_balls);
    case StressShotKind::CueMasse:
    case StressShotKind::CueAtPocket:
    case StressShotKind::CueCluster:
    case StressShotKind::CueTiny:
      return cueShot(kind, max_balls);
    default:
      return rectangleShot(kind, max_balls);
  }
}

}  // namespace

bool isStressShotKindName(const std::string& name) {
  for (int k = 0; k < static_cast<int>(StressShotKind::Count); ++k) {
    if (name == stressShotKindName(static_cast<StressShotKind>(k))) return true;
  }
  return false;
}

const char* stressShotKindName(StressShotKind kind) {
  switch (kind) {
    case StressShotKind::Random:
      return "random";
    case StressShotKind::GapShot:
      return "gap shot";
    case StressShotKind::FrozenLine:
      return "frozen line";
    case StressShotKind::FrozenTriangle:
      return "frozen triangle";
    case StressShotKind::CushionFrozen:
      return "ball against a cushion";
    case StressShotKind::Tiny:
      return "tiny speed";
    case StressShotKind::Grazing:
      return "grazing";
    case StressShotKind::NearSimultaneous:
      return "near-simultaneous";
    case StressShotKind::InTheMouth:
      return "in the mouth";
    case StressShotKind::CueMasse:
      return "cue masse";
    case StressShotKind::CueAtPocket:
      return "cue at pocket";
    case StressShotKind::CueCluster:
      return "cue cluster";
    case StressShotKind::CueTiny:
      return "cue tiny";
    case StressShotKind::Count:
      break;
  }
  return "?";
}

StressShotKind stressShotKindOf(long shot) {
  return static_cast<StressShotKind>(shot % static_cast<long>(StressShotKind::Count));
}

StressTables makeStressTables() {
  StressTables t;
  for (StressTableId id :
       {StressTableId::Rectangle, StressTableId::Pool9ft, StressTableId::Snooker12ft}) {
    t.tables.push_back(makeStressTable(id));
  }
  return t;
}

StressShot makeStressShot(const StressTables& tables, std::uint64_t seed, long shot,
                          int max_balls) {
  // Each shot has its own generator, so a shot can be made again from (seed, shot) alone.
  ShotMaker maker(seed * 0x9E3779B97F4A7C15ULL + static_cast<std::uint64_t>(shot), tables);
  return maker.make(stressShotKindOf(shot), max_balls);
}

nlohmann::json sceneFileJson(const StressShot& shot, long max_events) {
  nlohmann::json doc = shot.scene_json;
  doc["physics"] = {{"max_events", max_events}};
  return doc;
}

}  // namespace baize::engine
