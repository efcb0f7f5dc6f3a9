#include "engine/play/games/game_log.h"

#include <gtest/gtest.h>

namespace baize::engine {
namespace {

// The log read back gives the states played, bit for bit, for every game.
TEST(GameLog, StatesReadBackFromTheLogLines) {
  for (Game g : {Game::NineBall, Game::EightBall, Game::TenBall, Game::Snooker}) {
    PlayOptions options;
    options.max_shots = 6;
    options.seed = 5;
    const PlayedFrame frame = playFrame(gameSetup(g), options);
    for (std::size_t i = 0; i < frame.shots.size(); ++i) {
      const nlohmann::json line =
          nlohmann::json::parse(playedShotJson(frame.shots[i], static_cast<int>(i)).dump());
      EXPECT_EQ(gameStateFromJson(line.at("state"), "log"), frame.shots[i].state);
      EXPECT_EQ(gameStateFromJson(line.at("next"), "log"), frame.shots[i].next);
      EXPECT_EQ(line.at("index"), static_cast<int>(i));
    }
  }
}

TEST(GameLog, ReadingIsStrict) {
  GameState s;
  s.balls = {{"cue", Eigen::Vector2d(0.1, 0.2)}};
  nlohmann::json json = gameStateJson(s);
  json["extra"] = 1;
  EXPECT_THROW(gameStateFromJson(json, "log"), std::invalid_argument);
  json = gameStateJson(s);
  json["in_hand"] = "pocket";
  try {
    gameStateFromJson(json, "log");
    FAIL() << "an unknown in_hand was read";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("in_hand"), std::string::npos) << e.what();
  }
  json = gameStateJson(s);
  json["player"] = 2;
  EXPECT_THROW(gameStateFromJson(json, "log"), std::invalid_argument);
}

}  // namespace
}  // namespace baize::engine
