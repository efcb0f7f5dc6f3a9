#include "engine/play/games/game_play.h"

#include <gtest/gtest.h>

#include "engine/play/games/game_log.h"
#include "engine/play/games/game_rules.h"

namespace baize::engine {
namespace {

// A few shots of a frame are enough for determinism and the invariants; whole frames run in the
// command-line test.
constexpr int kShortFrame = 8;

std::string logOf(const PlayedFrame& frame) {
  std::string text;
  for (std::size_t i = 0; i < frame.shots.size(); ++i) {
    text += playedShotJson(frame.shots[i], static_cast<int>(i)).dump() + "\n";
  }
  return text;
}

PlayOptions shortFrame(std::uint64_t seed, double noise) {
  PlayOptions options;
  options.seed = seed;
  options.noise_scale = noise;
  options.max_shots = kShortFrame;
  return options;
}

TEST(GamePlay, AFrameIsTheSameForTheSameSeed) {
  for (Game g : {Game::NineBall, Game::Snooker}) {
    const GameSetup setup = gameSetup(g);
    const std::string first = logOf(playFrame(setup, shortFrame(7, 1)));
    EXPECT_EQ(first, logOf(playFrame(setup, shortFrame(7, 1))));
    EXPECT_NE(first, logOf(playFrame(setup, shortFrame(8, 1))));  // the break's stroke differs
  }
}

TEST(GamePlay, WithoutNoiseTheStrokeIsTheIntendedShot) {
  const PlayedFrame frame = playFrame(gameSetup(Game::TenBall), shortFrame(3, 0));
  for (const PlayedShot& s : frame.shots) {
    EXPECT_EQ(s.executed.heading_rad, s.intended.shot.heading_rad);
    EXPECT_EQ(s.executed.speed_mps, s.intended.shot.speed_mps);
  }
}

// Every shot starts from the state the previous one left; balls never overlap; the cue ball is
// placed only when in hand, where the rules allow; a frame stops when over.
TEST(GamePlay, ShotsChainAndRespectTheTable) {
  for (Game g : {Game::NineBall, Game::EightBall, Game::TenBall, Game::Snooker}) {
    const GameSetup setup = gameSetup(g);
    const PlayedFrame frame = playFrame(setup, shortFrame(11, 1));
    const double r = setup.scene.ball_set.radius_m;
    for (std::size_t i = 0; i < frame.shots.size(); ++i) {
      const PlayedShot& s = frame.shots[i];
      if (i > 0) {
        EXPECT_EQ(s.state, frame.shots[i - 1].next);
      }
      EXPECT_EQ(s.state.shots, static_cast<int>(i));
      if (s.intended.place) {
        EXPECT_EQ(placementRefusal(s.state, *s.intended.place, setup.scene.table, r), "");
      } else {
        EXPECT_EQ(s.state.in_hand, CueBallInHand::No);
      }
      for (std::size_t a = 1; a < s.next.balls.size(); ++a) {
        for (std::size_t b = 0; b < a; ++b) {
          if (b == 0 && s.next.in_hand != CueBallInHand::No) {
            continue;  // the cue ball is lifted
          }
          EXPECT_GE((s.next.balls[a].position_m - s.next.balls[b].position_m).norm(), 2 * r - 1e-9);
        }
      }
    }
    EXPECT_EQ(frame.final_state, frame.shots.back().next);
    EXPECT_EQ(frame.finished, frame.final_state.frame_over);
  }
}

TEST(GamePlay, PlayerZerosShotsComeFromTheSource) {
  int asked = 0;
  const GameSetup setup = gameSetup(Game::NineBall);
  const ShotSource source = [&](const GameState& state) -> std::optional<GameShot> {
    if (asked++ > 0) return std::nullopt;
    GameShot shot = breakShot(setup);
    shot.kind = "file";
    EXPECT_TRUE(state.break_shot);
    return shot;
  };
  const PlayedFrame frame = playFrame(setup, shortFrame(1, 0), source);
  EXPECT_EQ(frame.shots.front().intended.kind, "file");
  EXPECT_GE(asked, 1);
}

TEST(GamePlay, RefusesBadOptions) {
  PlayOptions options;
  options.max_shots = 0;
  EXPECT_THROW(playFrame(gameSetup(Game::NineBall), options), std::invalid_argument);
  EXPECT_THROW(scaledNoise(-1), std::invalid_argument);
  EXPECT_EQ(scaledNoise(2).aim_sigma_deg, 2 * ExecutionNoise().aim_sigma_deg);
}

}  // namespace
}  // namespace baize::engine
