#include "engine/play/shot_planner.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

namespace baize::engine {
namespace {

// Noise-free scores (lower is better) of shots that miss the goal: the pot made but the cue ball
// pocketed ranks above no pot at all. Shots that meet it score <= 1.
constexpr double kCueBallLostScore = 5;
constexpr double kNoPotScore = 10;
// The race draws its noisy samples from streams above this, apart from the grid's point streams.
constexpr std::uint64_t kRaceStreamBase = 1ull << 32;

const PlacedBall& placedBall(const Scene& scene, const std::string& id) {
  for (const PlacedBall& b : scene.balls) {
    if (b.id == id) return b;
  }
  throw std::invalid_argument("ball " + id + " is not in the scene " + scene.source);
}

double wrappedAngle(double angle_rad) { return std::remainder(angle_rad, 2 * M_PI); }

// Evenly spaced values from low to high inclusive (the middle for one value).
std::vector<double> evenly(double low, double high, int count) {
  if (count == 1) return {(low + high) / 2};
  std::vector<double> values;
  for (int i = 0; i < count; ++i) values.push_back(low + (high - low) * i / (count - 1));
  return values;
}

// How far inside the region the cue ball stopped: 0 at its centre, 1 on its edge (the straight-shot
// region: 0 met, 2 not met); 0 without a region.
double regionDepth(const Scene& scene, const PlanGoal& goal, const ShotOutcome& outcome) {
  if (!goal.region) return 0;
  const CueBallRegion& r = *goal.region;
  const Eigen::Vector2d c = outcome.cue_ball_final_m;
  switch (r.kind) {
    case CueBallRegion::Kind::Circle:
      return (c - r.centre_m).norm() / r.radius_m;
    case CueBallRegion::Kind::Rectangle: {
      const Eigen::Vector2d centre = (r.min_m + r.max_m) / 2, half = (r.max_m - r.min_m) / 2;
      return std::max(std::abs(c.x() - centre.x()) / half.x(),
                      std::abs(c.y() - centre.y()) / half.y());
    }
    case CueBallRegion::Kind::StraightShot:
      return straightShot(scene.table, scene.ball_set.radius_m, outcome, r.ball, r.pocket).clear
                 ? 0
                 : 2;
  }
  return 2;
}

bool pottedInPocket(const PlanGoal& goal, const ShotOutcome& outcome) {
  for (const PocketedBall& p : outcome.pocketed) {
    if (p.ball == goal.ball && p.pocket == goal.pocket) return true;
  }
  return false;
}

double noiseFreeScore(const Scene& scene, const PlanGoal& goal, const ShotOutcome& outcome) {
  if (!pottedInPocket(goal, outcome)) return kNoPotScore;
  if (outcome.cue_ball_pocketed) return kCueBallLostScore;
  return goalMet(scene, goal, outcome) ? std::min(1.0, regionDepth(scene, goal, outcome))
                                       : 1 + regionDepth(scene, goal, outcome);
}

// Counts simulated shots against the budget.
struct ShotCounter {
  long used = 0;
  const std::function<void()>* on_shot = nullptr;  // PlanOptions::on_shot, when counted for it
};

std::optional<ShotOutcome> runShot(Scene& scene, const physics::CueShot& shot, ShotCounter* count,
                                   SceneRun* run_out = nullptr) {
  ++count->used;
  if (count->on_shot != nullptr && *count->on_shot) (*count->on_shot)();
  scene.shot = shot;
  try {
    SceneRun run = runScene(scene);
    ShotOutcome outcome = shotOutcome(run, scene.cue_ball);
    if (run_out != nullptr) *run_out = std::move(run);
    return outcome;
  } catch (const BallLeftTableError&) {  // a fault, not a shot that merely failed
    throw;
  } catch (const std::exception&) {  // a miscue or a run over the event budget: no outcome
    return std::nullopt;
  }
}

struct Candidate {
  physics::CueShot shot;
  bool ran = false;
  double score = kNoPotScore;
  int successes = 0, samples = 0;
  int rounds = 0;  // race rounds survived
  double rate() const { return samples > 0 ? static_cast<double>(successes) / samples : 0; }
};

class Planner {
 public:
  Planner(const Scene& scene, const PlanGoal& goal, const PlanOptions& options)
      : scene_(scene), work_(scene), goal_(goal), options_(options) {
    const Eigen::Vector2d cue = placedBall(scene, scene.cue_ball).position_m;
    const Eigen::Vector2d object = placedBall(scene, goal.ball).position_m;
    const Eigen::Vector2d mouth = scene.table.pockets[goal.pocket].mouth_centre_m;
    const Eigen::Vector2d u = (mouth - object).normalized();
    pocket_direction_rad_ = std::atan2(u.y(), u.x());
    const Eigen::Vector2d ghost = object - 2 * scene.ball_set.radius_m * u;
    ghost_heading_rad_ = std::atan2(ghost.y() - cue.y(), ghost.x() - cue.x());
  }

  PlanResult run() {
    const PlanRanges& r = options_.ranges;
    const std::vector<double> speeds = evenly(r.min_speed_mps, r.max_speed_mps, kCoarseSpeeds);
    const std::vector<double> heights = evenly(-r.max_height, r.max_height, kCoarseHeights);
    const std::vector<double> sides = evenly(-r.max_side, r.max_side, kCoarseSides);
    const long noise_free_cap = options_.budget_shots / 2;  // the race gets at least half
    for (double v : speeds) {
      for (double b : heights) {
        for (double a : sides) {
          if (count_.used < noise_free_cap) addCandidate(v, b, a);
        }
      }
    }
    double speed_step = (speeds[1] - speeds[0]) / 2;
    double height_step = (heights[1] - heights[0]) / 2;
    double side_step = (sides[1] - sides[0]) / 2;
    for (int level = 0; level < kRefinements; ++level) {
      const std::vector<Candidate> centres = ranked(kRefinedCentres);
      for (const Candidate& centre : centres) {
        for (int dv = -1; dv <= 1; ++dv) {
          for (int db = -1; db <= 1; ++db) {
            for (int da = -1; da <= 1; ++da) {
              if ((dv == 0 && db == 0 && da == 0) || count_.used >= noise_free_cap) continue;
              const double v = centre.shot.speed_mps + dv * speed_step;
              const double b = centre.shot.height_offset + db * height_step;
              const double a = centre.shot.side_offset + da * side_step;
              if (v < r.min_speed_mps || v > r.max_speed_mps || std::abs(b) > r.max_height ||
                  std::abs(a) > r.max_side) {
                continue;
              }
              addCandidate(v, b, a);
            }
          }
        }
      }
      speed_step /= 2;
      height_step /= 2;
      side_step /= 2;
    }
    return race();
  }

 private:
  // The candidates ranked by their noise-free score (the order they were made breaks ties).
  std::vector<Candidate> ranked(int count) const {
    std::vector<Candidate> sorted = candidates_;
    std::stable_sort(sorted.begin(), sorted.end(), [](const Candidate& x, const Candidate& y) {
      return x.ran != y.ran ? x.ran : x.score < y.score;
    });
    if (static_cast<int>(sorted.size()) > count) sorted.resize(count);
    return sorted;
  }

  // A candidate at this speed and tip, aimed at the ghost ball with the throw corrected (secant on
  // the object ball's simulated direction), scored noise-free at the corrected aim.
  void addCandidate(double speed_mps, double height, double side) {
    Candidate c;
    c.shot = scene_.shot;
    c.shot.speed_mps = speed_mps;
    c.shot.height_offset = height;
    c.shot.side_offset = side;
    struct Trial {
      double heading_rad;
      std::optional<double> error_rad;
      std::optional<ShotOutcome> outcome;
    };
    const auto trial = [&](double heading_rad) {
      physics::CueShot shot = c.shot;
      shot.heading_rad = heading_rad;
      SceneRun run;
      Trial t{heading_rad, std::nullopt, runShot(work_, shot, &count_, &run)};
      if (t.outcome) {
        t.error_rad = objectDirectionError(run, scene_.cue_ball, goal_.ball, pocket_direction_rad_);
      }
      return t;
    };
    Trial best = trial(ghost_heading_rad_);
    Trial previous = best;
    if (best.error_rad && std::abs(*best.error_rad) > kThrowTolerance_rad) {
      Trial current = trial(ghost_heading_rad_ + kThrowProbe_rad);
      for (int k = 2; k < kMaxThrowIterations && current.error_rad && previous.error_rad; ++k) {
        if (std::abs(*current.error_rad) < std::abs(*best.error_rad)) best = current;
        if (std::abs(*best.error_rad) <= kThrowTolerance_rad) break;
        const double slope = (*current.error_rad - *previous.error_rad) /
                             (current.heading_rad - previous.heading_rad);
        if (slope == 0 || !std::isfinite(slope)) break;
        const double next = current.heading_rad - *current.error_rad / slope;
        previous = current;
        current = trial(next);
      }
      if (current.error_rad && std::abs(*current.error_rad) < std::abs(*best.error_rad)) {
        best = current;
      }
    }
    c.shot.heading_rad = best.heading_rad;
    c.ran = best.outcome.has_value();
    if (c.ran) c.score = noiseFreeScore(scene_, goal_, *best.outcome);
    candidates_.push_back(c);
  }

  // Successive halving: each round gives the survivors an equal share of the round's samples, then
  // keeps the better half by observed success rate (ties: the better noise-free score).
  PlanResult race() {
    std::vector<Candidate> field = ranked(kRaced);
    int rounds = 1;
    while ((1 << rounds) < static_cast<int>(field.size())) ++rounds;
    std::vector<int> alive(field.size());
    for (std::size_t i = 0; i < field.size(); ++i) alive[i] = static_cast<int>(i);
    for (int round = 0; round < rounds && !alive.empty(); ++round) {
      const long left = options_.budget_shots - count_.used;
      const long per = std::max(1L, left / (rounds - round) / static_cast<long>(alive.size()));
      for (int i : alive) {
        Candidate& c = field[i];
        for (long s = 0; s < per && count_.used < options_.budget_shots; ++s) {
          c.successes += sampleOnce(c.shot, kRaceStreamBase + i, c.samples);
          ++c.samples;
        }
        c.rounds = round + 1;
      }
      std::stable_sort(alive.begin(), alive.end(), [&](int x, int y) {
        const Candidate &a = field[x], &b = field[y];
        return a.rate() != b.rate() ? a.rate() > b.rate() : a.score < b.score;
      });
      if (round + 1 < rounds) alive.resize((alive.size() + 1) / 2);
    }
    std::vector<int> order(field.size());
    for (std::size_t i = 0; i < field.size(); ++i) order[i] = static_cast<int>(i);
    std::stable_sort(order.begin(), order.end(), [&](int x, int y) {
      const Candidate &a = field[x], &b = field[y];
      if (a.rounds != b.rounds) return a.rounds > b.rounds;
      return a.rate() != b.rate() ? a.rate() > b.rate() : a.score < b.score;
    });
    PlanResult result;
    result.shots_simulated = count_.used;
    result.candidates = static_cast<int>(candidates_.size());
    for (int i : order) {
      if (static_cast<int>(result.best.size()) >= options_.report) break;
      const Candidate& c = field[i];
      result.best.push_back({c.shot, wilsonEstimate(c.successes, c.samples), c.score});
    }
    return result;
  }

  bool sampleOnce(const physics::CueShot& shot, std::uint64_t stream, int sample) {
    NormalGenerator normal(sampleSeed(options_.seed, stream, static_cast<std::uint64_t>(sample)));
    const physics::CueShot noisy =
        perturbedShot(shot, drawExecutionError(options_.noise, scene_.ball_set.radius_m, &normal));
    const std::optional<ShotOutcome> o = runShot(work_, noisy, &count_);
    return o && goalMet(scene_, goal_, *o);
  }

  const Scene& scene_;
  Scene work_;  // the scene with the shot being tried
  const PlanGoal& goal_;
  const PlanOptions& options_;
  double pocket_direction_rad_ = 0;
  double ghost_heading_rad_ = 0;
  ShotCounter count_{0, &options_.on_shot};
  std::vector<Candidate> candidates_;
};

void validateOptions(const PlanOptions& options) {
  if (options.budget_shots < kMinPlanBudget) {
    throw std::invalid_argument("plan budget = " + std::to_string(options.budget_shots) +
                                " shots is not allowed: it must be at least " +
                                std::to_string(kMinPlanBudget));
  }
  const PlanRanges& r = options.ranges;
  if (!(r.min_speed_mps > 0 && r.min_speed_mps < r.max_speed_mps &&
        std::isfinite(r.max_speed_mps))) {
    throw std::invalid_argument("plan speed range is not allowed: it needs 0 < min < max, finite");
  }
  if (!(r.max_height >= 0 && r.max_side >= 0 &&
        std::hypot(r.max_height, r.max_side) < physics::kMiscueOffsetLimit)) {
    throw std::invalid_argument(
        "plan tip ranges are not allowed: they must stay inside the miscue "
        "limit");
  }
  if (options.report < 1) {
    throw std::invalid_argument("plan report = " + std::to_string(options.report) +
                                " is not allowed: at least 1");
  }
  validateExecutionNoise(options.noise);
}

}  // namespace

std::optional<double> objectDirectionError(const SceneRun& run, const std::string& cue,
                                           const std::string& object, double wanted_rad) {
  const auto index = [&](const std::string& id) {
    return static_cast<int>(std::find(run.ball_ids.begin(), run.ball_ids.end(), id) -
                            run.ball_ids.begin());
  };
  const int c = index(cue), o = index(object);
  for (const Event& e : run.result.events) {
    if (e.kind != EventKind::BallBall || (e.ball != c && e.other != c)) continue;
    if (e.ball != o && e.other != o) return std::nullopt;  // another ball first
    const Eigen::Vector3d v = e.after[e.ball == o ? 0 : 1].velocity;
    return wrappedAngle(std::atan2(v.y(), v.x()) - wanted_rad);
  }
  return std::nullopt;
}


bool goalMet(const Scene& scene, const PlanGoal& goal, const ShotOutcome& outcome) {
  if (!pottedInPocket(goal, outcome) || outcome.cue_ball_pocketed) return false;
  if (!goal.region) return true;
  Expectation e;
  e.kind = Expectation::Kind::CueBallStopsIn;
  e.region = *goal.region;
  return evaluateExpectation(e, outcome, scene).met;
}

void validatePlanGoal(const Scene& scene, const PlanGoal& goal) {
  bool found = false;
  for (const PlacedBall& b : scene.balls) found = found || b.id == goal.ball;
  if (!found || goal.ball == scene.cue_ball) {
    throw std::invalid_argument("ball " + goal.ball +
                                " is not allowed: it must be a ball of the scene other than the "
                                "cue ball");
  }
  if (goal.pocket < 0 || goal.pocket >= static_cast<int>(scene.table.pockets.size())) {
    throw std::invalid_argument("pocket " + std::to_string(goal.pocket) +
                                " is not allowed: the table has pockets 0 to " +
                                std::to_string(scene.table.pockets.size() - 1));
  }
  if (goal.region && goal.region->kind == CueBallRegion::Kind::Circle &&
      !(goal.region->radius_m > 0 && std::isfinite(goal.region->radius_m))) {
    throw std::invalid_argument("region radius = " + std::to_string(goal.region->radius_m) +
                                " m is not allowed: it must be > 0");
  }
  if (goal.region && goal.region->kind == CueBallRegion::Kind::Rectangle &&
      !(goal.region->min_m.x() < goal.region->max_m.x() &&
        goal.region->min_m.y() < goal.region->max_m.y())) {
    throw std::invalid_argument("region rectangle is not allowed: it needs x0 < x1 and y0 < y1");
  }
}

ProbabilityEstimate estimateGoal(const Scene& scene, const PlanGoal& goal,
                                 const physics::CueShot& shot, const ExecutionNoise& noise,
                                 int samples, std::uint64_t seed, std::uint64_t stream) {
  Scene work = scene;
  ShotCounter count;
  int successes = 0;
  for (int s = 0; s < samples; ++s) {
    NormalGenerator normal(sampleSeed(seed, stream, static_cast<std::uint64_t>(s)));
    const physics::CueShot noisy =
        perturbedShot(shot, drawExecutionError(noise, scene.ball_set.radius_m, &normal));
    const std::optional<ShotOutcome> o = runShot(work, noisy, &count);
    successes += o && goalMet(scene, goal, *o);
  }
  return wilsonEstimate(successes, samples);
}

PlanResult planShot(const Scene& scene, const PlanGoal& goal, const PlanOptions& options) {
  validatePlanGoal(scene, goal);
  validateOptions(options);
  return Planner(scene, goal, options).run();
}

PlanResult gridSearch(const Scene& scene, const PlanGoal& goal, const PlanOptions& options,
                      int samples_per_point) {
  validatePlanGoal(scene, goal);
  validateOptions(options);
  if (samples_per_point < 1) {
    throw std::invalid_argument("grid samples per point = " + std::to_string(samples_per_point) +
                                " is not allowed: at least 1");
  }
  const long points = options.budget_shots / samples_per_point;
  // Speed, tip height and tip side get n values each; the aim, which matters most, the rest.
  const int n = std::max(2, static_cast<int>(std::floor(std::pow(points, 0.25))));
  const int aims = std::max(2, static_cast<int>(points / (static_cast<long>(n) * n * n)));
  const Eigen::Vector2d cue = placedBall(scene, scene.cue_ball).position_m;
  const Eigen::Vector2d object = placedBall(scene, goal.ball).position_m;
  const double centre_rad = std::atan2(object.y() - cue.y(), object.x() - cue.x());
  const double reach_rad =
      std::asin(std::min(1.0, 2 * scene.ball_set.radius_m / (object - cue).norm()));
  const PlanRanges& r = options.ranges;
  struct Point {
    physics::CueShot shot;
    ProbabilityEstimate p;
  };
  std::vector<Point> tried;
  std::uint64_t stream = 0;
  for (double v : evenly(r.min_speed_mps, r.max_speed_mps, n)) {
    for (double b : evenly(-r.max_height, r.max_height, n)) {
      for (double a : evenly(-r.max_side, r.max_side, n)) {
        for (double phi : evenly(centre_rad - reach_rad, centre_rad + reach_rad, aims)) {
          physics::CueShot shot = scene.shot;
          shot.speed_mps = v;
          shot.height_offset = b;
          shot.side_offset = a;
          shot.heading_rad = phi;
          tried.push_back({shot, estimateGoal(scene, goal, shot, options.noise, samples_per_point,
                                              options.seed, stream++)});
        }
      }
    }
  }
  std::stable_sort(tried.begin(), tried.end(), [](const Point& x, const Point& y) {
    return x.p.probability > y.p.probability;
  });
  PlanResult result;
  result.candidates = static_cast<int>(tried.size());
  result.shots_simulated = static_cast<long>(tried.size()) * samples_per_point;
  for (const Point& p : tried) {
    if (static_cast<int>(result.best.size()) >= options.report) break;
    result.best.push_back({p.shot, p.p, 0});
  }
  return result;
}

}  // namespace baize::engine
