#include "engine/play/games/frame_summary.h"

#include <gtest/gtest.h>

namespace baize::engine {
namespace {

PlayedShot shot(Game game, int player, int potted, bool passes, GameFoul foul = GameFoul::None,
                int points = 0) {
  PlayedShot s;
  s.state.game = game;
  s.state.player = player;
  for (int i = 0; i < potted; ++i) s.facts.pocketed.push_back({std::to_string(i + 1), 0});
  s.decision.turn_passes = passes;
  s.decision.foul = foul;
  s.decision.points = points;
  return s;
}

TEST(FrameSummary, VisitsPotsFoulsAndRuns) {
  PlayedFrame f;
  f.shots = {shot(Game::NineBall, 0, 1, false), shot(Game::NineBall, 0, 0, true),
             shot(Game::NineBall, 1, 1, false), shot(Game::NineBall, 1, 2, false),
             shot(Game::NineBall, 1, 0, true, GameFoul::WrongBallFirst),
             shot(Game::NineBall, 0, 1, false)};
  f.finished = true;
  f.final_state.winner = 0;
  const FrameSummary s = summarizeFrame(f);
  EXPECT_EQ(s.players[0].shots, 3);
  EXPECT_EQ(s.players[0].visits, 2);
  EXPECT_EQ(s.players[0].potted, 2);
  EXPECT_EQ(s.players[1].visits, 1);
  EXPECT_EQ(s.players[1].potted, 3);
  EXPECT_EQ(s.players[1].fouls, 1);
  EXPECT_EQ(s.players[1].best_visit, 3);
  EXPECT_FALSE(s.run_out);
  EXPECT_FALSE(s.first_visit_run_out);
}

TEST(FrameSummary, BreakAndRunAndFirstVisit) {
  PlayedFrame f;
  f.shots = {shot(Game::NineBall, 0, 1, false), shot(Game::NineBall, 0, 1, false)};
  f.finished = true;
  f.final_state.winner = 0;
  EXPECT_TRUE(summarizeFrame(f).run_out);
  EXPECT_TRUE(summarizeFrame(f).first_visit_run_out);
  f.shots = {shot(Game::NineBall, 0, 0, true), shot(Game::NineBall, 1, 1, false)};
  f.final_state.winner = 1;
  EXPECT_FALSE(summarizeFrame(f).run_out);
  EXPECT_TRUE(summarizeFrame(f).first_visit_run_out);
}

TEST(FrameSummary, SnookerBreaksArePointsPerScoringVisit) {
  PlayedFrame f;
  f.shots = {shot(Game::Snooker, 0, 1, false, GameFoul::None, 1),
             shot(Game::Snooker, 0, 1, false, GameFoul::None, 7),
             shot(Game::Snooker, 0, 0, true), shot(Game::Snooker, 1, 0, true),
             shot(Game::Snooker, 0, 1, false, GameFoul::None, 1)};
  const FrameSummary s = summarizeFrame(f);
  EXPECT_EQ(s.breaks, (std::vector<int>{8, 1}));
  EXPECT_EQ(s.players[0].best_visit, 8);
}

}  // namespace
}  // namespace baize::engine
