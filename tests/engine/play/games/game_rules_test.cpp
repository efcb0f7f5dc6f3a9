#include "engine/play/games/game_rules.h"

#include <gtest/gtest.h>

#include "tests/engine/play/games/game_test_support.h"

namespace baize::engine {
namespace {

using Eigen::Vector2d;

TEST(GameRules, EveryGameStartsFromItsRackWithTheCueBallInHand) {
  for (Game g : {Game::NineBall, Game::TenBall, Game::EightBall}) {
    const GameState s = initialGameState(g, test::poolTable(), builtinBallSet("pool"));
    EXPECT_EQ(s.balls.front().id, "cue");
    EXPECT_EQ(s.in_hand, CueBallInHand::BehindHeadString);
    EXPECT_TRUE(s.break_shot);
    EXPECT_EQ(s.player, 0);
  }
  EXPECT_EQ(initialGameState(Game::NineBall, test::poolTable(), builtinBallSet("pool")).balls.size(), 10u);
  EXPECT_EQ(initialGameState(Game::EightBall, test::poolTable(), builtinBallSet("pool")).balls.size(), 16u);
  const GameState snooker =
      initialGameState(Game::Snooker, test::snookerTable(), builtinBallSet("snooker"));
  EXPECT_EQ(snooker.balls.size(), 22u);
  EXPECT_EQ(snooker.in_hand, CueBallInHand::InD);
  EXPECT_EQ(snooker.ball_on, "red");
  EXPECT_THROW(initialGameState(Game::Snooker, test::poolTable(), builtinBallSet("pool")),
               std::invalid_argument);
}

TEST(GameRules, NamesRoundTrip) {
  for (const std::string& name : gameNames()) EXPECT_EQ(gameName(*gameNamed(name)), name);
  EXPECT_FALSE(gameNamed("straight-pool"));
}

TEST(GameRules, LegalTargetsPerGame) {
  const GameState nine = initialGameState(Game::NineBall, test::poolTable(), builtinBallSet("pool"));
  EXPECT_EQ(legalTargets(nine), std::vector<std::string>{"1"});
  const GameState eight = initialGameState(Game::EightBall, test::poolTable(), builtinBallSet("pool"));
  EXPECT_EQ(legalTargets(eight).size(), 14u);  // open table: all but the 8
  const GameState snooker =
      initialGameState(Game::Snooker, test::snookerTable(), builtinBallSet("snooker"));
  EXPECT_EQ(legalTargets(snooker).size(), 15u);
}

TEST(GameRules, PlacementFromHand) {
  const Table& t = test::poolTable();
  const double r = test::poolRadius();
  GameState s = initialGameState(Game::NineBall, t, builtinBallSet("pool"));
  const double head = t.pool_markings->head_string_x_m;
  EXPECT_EQ(placementRefusal(s, Vector2d(head - 0.1, 0.2), t, r), "");
  EXPECT_NE(placementRefusal(s, Vector2d(head + 0.1, 0.2), t, r).find("behind the head string"),
            std::string::npos);
  s.in_hand = CueBallInHand::Anywhere;
  EXPECT_EQ(placementRefusal(s, Vector2d(head + 0.1, 0.2), t, r), "");
  EXPECT_NE(placementRefusal(s, s.balls[1].position_m + Vector2d(r, 0), t, r).find("touches ball 1"),
            std::string::npos);
  EXPECT_NE(placementRefusal(s, Vector2d(t.length_m, 0), t, r).find("off the playing surface"),
            std::string::npos);
  s.in_hand = CueBallInHand::No;
  EXPECT_EQ(placementRefusal(s, Vector2d(-1, 0), t, r), "the cue ball is not in hand");
  const Table& st = test::snookerTable();
  const GameState snooker = initialGameState(Game::Snooker, st, builtinBallSet("snooker"));
  const SnookerMarkings& m = *st.snooker_markings;
  EXPECT_EQ(placementRefusal(snooker, m.brown_spot_m + Vector2d(-0.1, 0.15), st, test::snookerRadius()), "");
  EXPECT_NE(placementRefusal(snooker, m.brown_spot_m + Vector2d(0.1, 0), st, test::snookerRadius())
                .find("not in the D"),
            std::string::npos);
}

}  // namespace
}  // namespace baize::engine
