#include "engine/play/games/game_player.h"

#include <algorithm>
#include <cmath>

#include "engine/play/games/game_rules.h"
#include "engine/play/games/pot_ease.h"
#include "engine/play/shot_planner.h"

namespace baize::engine {
namespace {

using Eigen::Vector2d;

constexpr double kDegToRad = M_PI / 180;
constexpr double kPotSpeeds_mps[] = {0.8, 1.3, 1.9, 2.7, 3.6};  // soft to firm
constexpr double kPotHeights[] = {-0.35, -0.15, 0.0, 0.2, 0.4};  // draw to follow (units of R)
constexpr double kSafetySpeeds_mps[] = {1.0, 2.0};     // enough to reach a cushion after contact
constexpr double kHandDistances_m[] = {0.3, 0.6};      // cue ball behind the ghost ball, from hand
constexpr double kHandAngles_deg[] = {0.0, 25.0, -25.0};  // cut angles given to a placed cue ball
constexpr int kSafetyTargets = 3;                      // nearest legal balls tried for a safety
constexpr double kSafetyThickness = 0.6;  // aim offsets of a safety, as a share of a full ball
constexpr int kAreaSteps = 4;  // grid steps across the D or behind the head string
constexpr double kThrowProbe_rad = 1.7e-3;  // secant's first step on the aim: 0.1 deg

struct PotPlan {
  std::string target;
  int pocket = 0;
  std::optional<Vector2d> place;
  double ease = 0;
};

struct Scored {
  GameShot shot;
  double value = 0;  // the noise-free value, then the noisy estimate for finalists
};

double radiusOf(const GameSetup& setup) { return setup.scene.ball_set.radius_m; }

Vector2d cueAt(const GameState& state, const std::optional<Vector2d>& place) {
  return place ? *place : state.balls.front().position_m;
}

// The allowed places of a grid over the area a restricted cue ball in hand may take: the D
// (snooker) or the part of the table behind the head string (pool).
std::vector<Vector2d> areaPlaces(const GameSetup& setup, const GameState& state) {
  const Table& table = setup.scene.table;
  std::vector<Vector2d> grid;
  if (state.in_hand == CueBallInHand::InD) {
    const SnookerMarkings& m = table.snooker_markings.value();
    for (int ring = 0; ring <= kAreaSteps; ++ring) {
      for (int a = 0; a <= 2 * kAreaSteps; ++a) {
        const double angle = M_PI / 2 + M_PI * a / (2 * kAreaSteps);
        grid.push_back(m.brown_spot_m + m.d_radius_m * ring / kAreaSteps *
                                            Vector2d(std::cos(angle), std::sin(angle)));
      }
    }
  } else if (state.in_hand == CueBallInHand::BehindHeadString) {
    const double head = table.pool_markings.value().head_string_x_m;
    const double x0 = -table.length_m / 2, half_width = table.width_m / 2;
    for (int i = 1; i <= kAreaSteps; ++i) {
      for (int j = 1; j < 2 * kAreaSteps; ++j) {
        grid.emplace_back(x0 + (head - x0) * i / kAreaSteps,
                          -half_width + half_width * j / kAreaSteps);
      }
    }
  }
  std::vector<Vector2d> allowed;
  for (const Vector2d& p : grid) {
    if (placementRefusal(state, p, table, radiusOf(setup)).empty()) allowed.push_back(p);
  }
  return allowed;
}

std::vector<PotPlan> potPlans(const GameSetup& setup, const GameState& state, int keep) {
  const Table& table = setup.scene.table;
  const double r = radiusOf(setup);
  std::vector<PotPlan> plans;
  const std::vector<Vector2d> area = areaPlaces(setup, state);
  for (const std::string& target : legalTargets(state)) {
    for (int k = 0; k < static_cast<int>(table.pockets.size()); ++k) {
      if (state.in_hand == CueBallInHand::No) {
        const double ease = potEase(state.balls, cueAt(state, {}), target, k, table, r);
        if (ease > 0) plans.push_back({target, k, std::nullopt, ease});
        continue;
      }
      for (const Vector2d& place : area) {
        const double ease = potEase(state.balls, place, target, k, table, r);
        if (ease > 0) plans.push_back({target, k, place, ease});
      }
      if (state.in_hand != CueBallInHand::Anywhere) continue;
      const Vector2d object = state.ball(target)->position_m;
      const Vector2d ghost = ghostBall(object, table.pockets[k], r);
      const Vector2d u = (table.pockets[k].mouth_centre_m - object).normalized();
      for (double d : kHandDistances_m) {
        for (double a : kHandAngles_deg) {
          const double c = std::cos(a * kDegToRad), s = std::sin(a * kDegToRad);
          const Vector2d place = ghost - d * Vector2d(c * u.x() - s * u.y(), s * u.x() + c * u.y());
          if (!placementRefusal(state, place, table, r).empty()) continue;
          const double ease = potEase(state.balls, place, target, k, table, r);
          if (ease > 0) plans.push_back({target, k, place, ease});
        }
      }
    }
  }
  std::stable_sort(plans.begin(), plans.end(),
                   [](const PotPlan& a, const PotPlan& b) { return a.ease > b.ease; });
  if (static_cast<int>(plans.size()) > keep) plans.resize(keep);
  return plans;
}

// The value of a shot's noise-free (or one noisy) run: a kept table scores kKeepShare plus the
// rest times the next pot's ease; a safety (`safety`) scores kSafetyShare x the opponent's
// difficulty when legal; a foul or a lost frame 0.
double shotValue(const GameSetup& setup, const GameState& state, const GameShot& shot, bool safety) {
  const std::optional<ShotFacts> facts = simulateFacts(shotScene(setup, state, shot));
  if (!facts) return 0;
  const Ruling r = ruleShot(state, *facts, shot.call, setup.scene.table, radiusOf(setup));
  if (r.next.frame_over) return r.next.winner == state.player ? 1 : 0;
  if (r.decision.foul != GameFoul::None) return 0;
  const double ease = bestPotEase(r.next, setup.scene.table, radiusOf(setup));
  if (!r.decision.turn_passes) return kKeepShare + (1 - kKeepShare) * ease;
  return safety ? kSafetyShare * (1 - ease) : 0;
}

// The heading that sends the object ball along the line to the pocket's mouth, the throw
// corrected by one secant step on the simulated direction (the ghost-ball heading when the cue
// ball would not hit it first).
double aimedHeading(const GameSetup& setup, const GameState& state, const GameShot& shot,
                    const PotPlan& plan) {
  const Table& table = setup.scene.table;
  const Vector2d object = state.ball(plan.target)->position_m;
  const Vector2d u = (table.pockets[plan.pocket].mouth_centre_m - object).normalized();
  const Vector2d to_ghost = ghostBall(object, table.pockets[plan.pocket], radiusOf(setup)) -
                            cueAt(state, plan.place);
  const double ghost_heading = std::atan2(to_ghost.y(), to_ghost.x());
  const double wanted = std::atan2(u.y(), u.x());
  const auto error = [&](double heading) -> std::optional<double> {
    GameShot trial = shot;
    trial.shot.heading_rad = heading;
    SceneRun run;
    if (!simulateFacts(shotScene(setup, state, trial), &run)) return std::nullopt;
    return objectDirectionError(run, "cue", plan.target, wanted);
  };
  const std::optional<double> e0 = error(ghost_heading);
  const std::optional<double> e1 = e0 ? error(ghost_heading + kThrowProbe_rad) : std::nullopt;
  if (!e1 || *e1 == *e0) return ghost_heading;
  return ghost_heading - *e0 * kThrowProbe_rad / (*e1 - *e0);
}

std::vector<Scored> potCandidates(const GameSetup& setup, const GameState& state,
                                  const PlayerOptions& options) {
  std::vector<Scored> scored;
  for (const PotPlan& plan : potPlans(setup, state, options.candidates)) {
    for (double speed : kPotSpeeds_mps) {
      GameShot shot;
      shot.place = plan.place;
      shot.shot.speed_mps = speed;
      shot.call = {plan.target, plan.pocket, false};
      shot.kind = "pot";
      shot.shot.heading_rad = aimedHeading(setup, state, shot, plan);
      for (double height : kPotHeights) {
        shot.shot.height_offset = height;
        scored.push_back({shot, shotValue(setup, state, shot, false)});
      }
    }
  }
  return scored;
}

// A place for the cue ball from hand when no pot plan gave one: the first allowed point of the
// restricted area, or on rings around the legal balls.
std::optional<Vector2d> anyPlace(const GameSetup& setup, const GameState& state) {
  if (state.in_hand != CueBallInHand::Anywhere) {
    const std::vector<Vector2d> area = areaPlaces(setup, state);
    return area.empty() ? std::nullopt : std::optional<Vector2d>(area.front());
  }
  for (const std::string& target : legalTargets(state)) {
    for (double d : kHandDistances_m) {
      for (int step = 0; step < 8; ++step) {
        const double a = step * M_PI / 4;
        const Vector2d p = state.ball(target)->position_m + d * Vector2d(std::cos(a), std::sin(a));
        if (placementRefusal(state, p, setup.scene.table, radiusOf(setup)).empty()) return p;
      }
    }
  }
  return std::nullopt;
}

std::vector<Scored> safetyCandidates(const GameSetup& setup, const GameState& state) {
  std::optional<Vector2d> place;
  if (state.in_hand != CueBallInHand::No) place = anyPlace(setup, state);
  const Vector2d cue = cueAt(state, place);
  std::vector<std::string> targets = legalTargets(state);
  std::stable_sort(targets.begin(), targets.end(), [&](const std::string& a, const std::string& b) {
    return (state.ball(a)->position_m - cue).norm() < (state.ball(b)->position_m - cue).norm();
  });
  if (static_cast<int>(targets.size()) > kSafetyTargets) targets.resize(kSafetyTargets);
  std::vector<Scored> scored;
  for (const std::string& target : targets) {
    const Vector2d to = state.ball(target)->position_m - cue;
    const double offset = std::asin(std::min(1.0, kSafetyThickness * 2 * radiusOf(setup) / to.norm()));
    for (double aim : {0.0, offset, -offset}) {
      for (double speed : kSafetySpeeds_mps) {
        GameShot shot;
        shot.place = place;
        shot.shot.heading_rad = std::atan2(to.y(), to.x()) + aim;
        shot.shot.speed_mps = speed;
        shot.call = {target, -1, false};
        shot.kind = "safety";
        scored.push_back({shot, shotValue(setup, state, shot, true)});
      }
    }
  }
  return scored;
}

// The finalists' values re-estimated as the mean over noisy samples of their strokes.
void sampleFinalists(const GameSetup& setup, const GameState& state, const PlayerOptions& options,
                     std::uint64_t seed, std::vector<Scored>* finalists) {
  for (std::size_t f = 0; f < finalists->size(); ++f) {
    Scored& c = (*finalists)[f];
    double total = 0;
    for (int s = 0; s < options.noisy_samples; ++s) {
      NormalGenerator normal(sampleSeed(seed, f, s));
      GameShot noisy = c.shot;
      noisy.shot = perturbedShot(c.shot.shot,
                                 drawExecutionError(options.noise, radiusOf(setup), &normal));
      total += shotValue(setup, state, noisy, c.shot.kind == "safety");
    }
    c.value = total / std::max(1, options.noisy_samples);
  }
}

Scored best(const std::vector<Scored>& scored) {
  return *std::max_element(scored.begin(), scored.end(), [](const Scored& a, const Scored& b) {
    return a.value < b.value;  // the first of equals stays
  });
}

}  // namespace

GameShot chooseShot(const GameSetup& setup, const GameState& state, const PlayerOptions& options,
                    std::uint64_t seed) {
  if (state.break_shot) return breakShot(setup);
  std::vector<Scored> pots = potCandidates(setup, state, options);
  std::stable_sort(pots.begin(), pots.end(),
                   [](const Scored& a, const Scored& b) { return a.value > b.value; });
  std::vector<Scored> finalists;
  for (const Scored& p : pots) {
    if (p.value > 0 && static_cast<int>(finalists.size()) < options.finalists) finalists.push_back(p);
  }
  sampleFinalists(setup, state, options, seed, &finalists);
  const double pot_value = finalists.empty() ? 0 : best(finalists).value;
  if (pot_value >= kSafetyShare) return best(finalists).shot;
  std::vector<Scored> safeties = safetyCandidates(setup, state);
  if (!finalists.empty()) safeties.push_back(best(finalists));
  if (safeties.empty()) {  // nothing on the table to play at: a soft stroke along the table
    GameShot shot;
    shot.place = state.in_hand != CueBallInHand::No ? anyPlace(setup, state) : std::nullopt;
    shot.shot.speed_mps = kSafetySpeeds_mps[0];
    shot.kind = "safety";
    return shot;
  }
  return best(safeties).shot;
}

}  // namespace baize::engine
