// What a game is played with: the table, the balls and the break shot of the game's break scene
// (assets/scenes: 9-ball-break, 8-ball-break, snooker-break-off; 10-ball breaks as the 9-ball scene
// does, at its own rack), and one shot of a
// game as a player plays it: the cue ball's place from hand, the cue shot, the call.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "engine/io/scene.h"
#include "engine/play/games/game_state.h"
#include "physics/cue_strike.h"

namespace baize::engine {

struct GameSetup {
  Game game = Game::NineBall;
  Scene scene;  // the break scene: its table, ball set, physics; its shot and cue ball the break
};

// The setup of `game` from its break scene in the assets folder.
GameSetup gameSetup(Game game);

struct GameShot {
  std::optional<Eigen::Vector2d> place;  // the cue ball's place, when it is in hand
  physics::CueShot shot;
  ShotCall call;
  std::string kind;  // "break", "pot", "safety" or "file" (a shot read from a file)
};

// The break as the scene plays it: the cue ball on the scene's place, its shot.
GameShot breakShot(const GameSetup& setup);

// The scene of a shot from `state`: the state's balls with the cue ball at its place, the shot.
Scene shotScene(const GameSetup& setup, const GameState& state, const GameShot& shot);

// The facts of the scene's shot when it runs; nothing when the strike is refused (a miscue) or the
// run fails (the event budget).
std::optional<ShotFacts> simulateFacts(const Scene& scene, SceneRun* run_out = nullptr);

// The facts of a shot that did not run: nothing moved, nothing hit.
ShotFacts standingFacts(const GameState& state);

}  // namespace baize::engine
