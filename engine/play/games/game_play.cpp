#include "engine/play/games/game_play.h"

#include <cmath>
#include <stdexcept>

#include "engine/play/games/game_rules.h"
#include "physics/value_text.h"

namespace baize::engine {
namespace {

// Streams of the frame's random draws: the stroke of shot i uses sampleSeed(seed, i,
// kStrokeStream); the player's own noisy look-ahead uses its seeds below it.
constexpr std::uint64_t kStrokeStream = 1ull << 40;
constexpr std::uint64_t kPlayerStreamBase = 1ull << 20;
constexpr std::uint64_t kRackStream = 1ull << 41;  // the rack's jitter

}  // namespace

ExecutionNoise scaledNoise(double scale) {
  if (!(std::isfinite(scale) && scale >= 0)) {
    physics::rejectValue("noise scale", scale, "it must be finite and >= 0");
  }
  const ExecutionNoise defaults;
  ExecutionNoise noise;
  noise.tip_offset_sigma_m = scale * defaults.tip_offset_sigma_m;
  noise.elevation_sigma_deg = scale * defaults.elevation_sigma_deg;
  noise.aim_sigma_deg = scale * defaults.aim_sigma_deg;
  noise.speed_sigma_mps = scale * defaults.speed_sigma_mps;
  return noise;
}

PlayedShot playShot(const GameSetup& setup, const GameState& state, const PlayOptions& options,
                    int index, const ShotSource& player0) {
  PlayerOptions player = options.player;
  player.noise = scaledNoise(options.noise_scale);
  PlayedShot played;
  played.state = state;
  std::optional<GameShot> from_source;
  if (state.player == 0 && player0) from_source = player0(state);
  played.intended = from_source ? *from_source
                                : chooseShot(setup, state, player,
                                             sampleSeed(options.seed, index, kPlayerStreamBase));
  played.executed = played.intended.shot;
  if (options.noise_scale > 0) {
    NormalGenerator normal(sampleSeed(options.seed, static_cast<std::uint64_t>(index), kStrokeStream));
    played.executed = perturbedShot(
        played.intended.shot,
        drawExecutionError(player.noise, setup.scene.ball_set.radius_m, &normal));
  }
  GameShot stroke = played.intended;
  stroke.shot = played.executed;
  const Scene scene = shotScene(setup, state, stroke);
  std::optional<ShotFacts> facts = simulateFacts(scene);
  played.ran = facts.has_value();
  if (!facts) {
    GameState placed = state;
    placed.balls = scene.balls;
    facts = standingFacts(placed);
  }
  played.facts = *facts;
  Ruling ruling = ruleShot(state, played.facts, played.intended.call, setup.scene.table,
                           setup.scene.ball_set.radius_m);
  played.decision = ruling.decision;
  played.next = ruling.next;
  return played;
}

GameState frameStart(const GameSetup& setup, const PlayOptions& options) {
  RackOptions rack;
  rack.gap_m = jitteredRackGap_m(kRackJitter_m);
  rack.jitter_seed = sampleSeed(options.seed, 0, kRackStream);
  rack.jitter_radius_m = kRackJitter_m;
  return initialGameState(setup.game, setup.scene.table, setup.scene.ball_set, rack);
}

PlayedFrame playFrame(const GameSetup& setup, const PlayOptions& options,
                      const ShotSource& player0) {
  if (options.max_shots < 1) {
    physics::rejectValue("max_shots", options.max_shots, "it must be at least 1");
  }
  PlayedFrame frame;
  GameState state = frameStart(setup, options);
  while (!state.frame_over && static_cast<int>(frame.shots.size()) < options.max_shots) {
    frame.shots.push_back(
        playShot(setup, state, options, static_cast<int>(frame.shots.size()), player0));
    state = frame.shots.back().next;
  }
  frame.final_state = state;
  frame.finished = state.frame_over;
  return frame;
}

}  // namespace baize::engine
