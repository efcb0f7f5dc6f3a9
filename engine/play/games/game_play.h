// Playing a frame (`baize play`): from the break, each shot chosen by the game player (or, for
// player 0, read from a source such as a file), struck with execution noise, simulated, and ruled
// on, until the frame is over or a shot limit is reached. Deterministic for a seed.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "engine/play/games/game_player.h"

namespace baize::engine {

struct PlayOptions {
  double noise_scale = 1;  // the execution noise as a multiple of the default sigmas; 0: none
  std::uint64_t seed = 1;
  int max_shots = 400;  // a frame not over after this many shots stops unfinished
  PlayerOptions player;  // its noise is set from noise_scale (a player expects its own errors)
};

// The default execution noise (engine/play/execution_noise.h) times `scale` >= 0.
ExecutionNoise scaledNoise(double scale);

// Player 0's shots from elsewhere: the shot for this state, or nothing when the source has no
// more (the game player takes over). It may throw to refuse a shot it cannot play.
using ShotSource = std::function<std::optional<GameShot>(const GameState& state)>;

struct PlayedShot {
  GameState state;  // before the shot
  GameShot intended;
  physics::CueShot executed;  // with the execution error
  bool ran = true;            // false: a miscue (nothing moved, nothing hit)
  ShotFacts facts;
  Decision decision;
  GameState next;
};

struct PlayedFrame {
  std::vector<PlayedShot> shots;
  GameState final_state;
  bool finished = false;  // the frame is over (else the shot limit stopped it)
};

// The rack each ball of which lies within this radius of its place (m), drawn from the frame's
// seed: the largest jitter racks take (engine/io/rack.h), under a millimetre as real racks are.
constexpr double kRackJitter_m = kMaxJitterRadius_m;

// The state before the break: the game's rack jittered by the seed, the cue ball in hand.
GameState frameStart(const GameSetup& setup, const PlayOptions& options);

// Plays one frame of `setup.game`. Throws std::invalid_argument for options out of range.
PlayedFrame playFrame(const GameSetup& setup, const PlayOptions& options,
                      const ShotSource& player0 = {});

// The same, one shot at a time: the next shot from `state` (shot number `index` of the frame).
PlayedShot playShot(const GameSetup& setup, const GameState& state, const PlayOptions& options,
                    int index, const ShotSource& player0);

}  // namespace baize::engine
