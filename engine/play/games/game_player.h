// The player of `baize play`: position play shot after shot (docs/games.md). For each legal ball
// and pocket (and, with the cue ball in hand, a few places behind the ghost ball), ranked by their
// geometric ease, it tries a few speeds and tip heights aimed with the throw corrected, keeps the
// shots that keep the table, scores them by the ease of the best next pot they leave, and samples
// the best under execution noise: value = P(keeping the table) x (a share for the position). When
// no pot is worth it, a safety: a legal hit on a legal ball that leaves the opponent the hardest
// best pot.
#pragma once

#include <cstdint>

#include "engine/play/execution_noise.h"
#include "engine/play/games/game_setup.h"

namespace baize::engine {

struct PlayerOptions {
  ExecutionNoise noise;   // the errors the player expects of its own strokes
  int candidates = 6;      // pots kept from the geometric ranking
  int finalists = 6;       // noise-free best shots sampled with noise
  int noisy_samples = 16;  // samples per finalist
};

// The value of a shot that keeps the table: this share for keeping it, the rest for the ease of
// the next pot it leaves.
constexpr double kKeepShare = 0.6;
// A legal safety is worth this share of the opponent's difficulty (1 - their best ease); a pot
// whose sampled value reaches it is played without trying safeties.
constexpr double kSafetyShare = 0.4;

// The shot the player chooses; deterministic for `seed`.
GameShot chooseShot(const GameSetup& setup, const GameState& state, const PlayerOptions& options,
                    std::uint64_t seed);

}  // namespace baize::engine
