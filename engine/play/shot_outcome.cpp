#include "engine/play/shot_outcome.h"

#include <stdexcept>
#include <utility>

#include "engine/play/model_range.h"

namespace baize::engine {

const FinalBall* ShotOutcome::ball(const std::string& id) const {
  for (const FinalBall& b : final_balls) {
    if (b.id == id) return &b;
  }
  return nullptr;
}

bool ShotOutcome::wasPocketed(const std::string& id) const {
  const FinalBall* b = ball(id);
  return b != nullptr && b->pocketed;
}

ShotOutcome shotOutcome(const SceneRun& run, const std::string& cue_ball) {
  int cue = -1;
  for (std::size_t i = 0; i < run.ball_ids.size(); ++i) {
    if (run.ball_ids[i] == cue_ball) cue = static_cast<int>(i);
  }
  if (cue < 0) {
    throw std::invalid_argument("cue ball '" + cue_ball +
                                "' is not allowed: it must be one of the run's balls");
  }
  ShotOutcome outcome;
  outcome.cue_ball = cue_ball;
  outcome.events = static_cast<long>(run.result.events.size());
  for (std::size_t i = 0; i < run.ball_ids.size(); ++i) {
    const BallRecord& record = run.result.final_balls.at(i);
    outcome.final_balls.push_back({run.ball_ids[i], record.state.position, record.pocketed});
  }
  for (const Event& e : run.result.events) {
    switch (e.kind) {
      case EventKind::BallBall:
        if (!outcome.first_hit && (e.ball == cue || e.other == cue)) {
          outcome.first_hit = run.ball_ids.at(e.ball == cue ? e.other : e.ball);
        }
        break;
      case EventKind::Cushion:
      case EventKind::Jaw:
        if (e.ball == cue && !outcome.first_hit) ++outcome.cushions_before_first_hit;
        ++outcome.final_balls.at(e.ball).cushion_contacts;
        ++outcome.cushion_contacts;
        break;
      case EventKind::Pocket:
        outcome.pocketed.push_back({run.ball_ids.at(e.ball), e.index});
        break;
      case EventKind::StateChange:
        break;
    }
  }
  outcome.cue_ball_pocketed = run.result.final_balls.at(cue).pocketed;
  outcome.cue_ball_final_m = run.result.final_balls.at(cue).state.position;
  if (outcome.cue_ball_pocketed) {
    outcome.foul = Foul::CueBallPocketed;
  } else if (!outcome.first_hit) {
    outcome.foul = Foul::NoBallHit;
  }
  return outcome;
}

ShotResult shotResult(Scene scene, const SceneRun& run, bool with_recording) {
  const ShotOutcome outcome = shotOutcome(run, scene.cue_ball);
  ShotResult r;
  r.source = scene.source;
  r.scene = std::move(scene);
  r.params = simulationParamsFor(r.scene);
  r.physics = physicsJson(r.params, cueStrikeParamsFor(r.scene));
  r.end_time_s = run.result.end_time_s;
  r.first_ball_hit = outcome.first_hit;
  r.cushions_before_first_hit = outcome.cushions_before_first_hit;
  r.pocketed = outcome.pocketed;
  r.foul = outcome.foul;
  r.event_count = outcome.events;
  for (const FinalBall& b : outcome.final_balls) {
    r.final_positions_m.push_back(b.pocketed ? std::nullopt : std::optional(b.position_m));
    r.cushion_contacts.push_back(b.cushion_contacts);
  }
  r.beyond_model_range = impactsBeyondModelRange(r.scene, run);
  r.predictions_solved = run.result.predictions;
  r.predictions_skipped = run.result.skipped_predictions;
  if (with_recording) {
    r.events = run.result.events;
    if (run.result.trajectories.size() == run.ball_ids.size()) {
      r.trajectories = run.result.trajectories;
    }
  }
  return r;
}

}  // namespace baize::engine
