#include "engine/play/games/game_setup.h"

#include "engine/play/games/shot_facts.h"

namespace baize::engine {

GameSetup gameSetup(Game game) {
  const std::string file = game == Game::Snooker  ? "snooker-break-off.json"
                           : game == Game::TenBall ? "9-ball-break.json"
                                                   : std::string(gameName(game)) + "-break.json";
  GameSetup setup{game, loadScene(assetsDirectory() + "/scenes/" + file)};
  // 10-ball breaks as 9-ball does (the 1 on the foot spot, the same stroke) at its own rack.
  if (game == Game::TenBall) {
    setup.scene.balls = placeRack(gameName(game), setup.scene.table, setup.scene.ball_set);
  }
  return setup;
}

GameShot breakShot(const GameSetup& setup) {
  GameShot shot;
  for (const PlacedBall& b : setup.scene.balls) {
    if (b.id == setup.scene.cue_ball) shot.place = b.position_m;
  }
  shot.shot = setup.scene.shot;
  shot.kind = "break";
  return shot;
}

Scene shotScene(const GameSetup& setup, const GameState& state, const GameShot& shot) {
  Scene scene = setup.scene;
  scene.balls = state.balls;
  scene.cue_ball = "cue";
  if (shot.place) scene.balls.front().position_m = *shot.place;
  scene.shot = shot.shot;
  return scene;
}

std::optional<ShotFacts> simulateFacts(const Scene& scene, SceneRun* run_out) {
  SceneRun run;
  try {
    run = runScene(scene);
  } catch (const BallLeftTableError&) {  // a fault of the event loop, not a shot that failed
    throw;
  } catch (const std::exception&) {  // a miscue or a run over the event budget
    return std::nullopt;
  }
  ShotFacts facts = shotFacts(run.ball_ids, run.result, scene.cue_ball);
  if (run_out != nullptr) *run_out = std::move(run);
  return facts;
}

ShotFacts standingFacts(const GameState& state) {
  ShotFacts facts;
  facts.final_balls = state.balls;
  return facts;
}

}  // namespace baize::engine
