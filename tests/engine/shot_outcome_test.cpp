#include "engine/shot_outcome.h"

#include <gtest/gtest.h>

#include "engine/json_reader.h"

namespace baize::engine {
namespace {

Event contact(EventKind kind, int ball, int other, int index) {
  Event e;
  e.kind = kind;
  e.ball = ball;
  e.other = other;
  e.index = index;
  return e;
}

// Balls "cue", "1", "2" at rest where the events leave them; `pocketed` flags per ball.
SceneRun handMadeRun(const std::vector<Event>& events, std::vector<bool> pocketed) {
  SceneRun run;
  run.ball_ids = {"cue", "1", "2"};
  run.result.events = events;
  for (int i = 0; i < 3; ++i) {
    BallRecord record;
    record.state.position = Eigen::Vector2d(0.1 * i, -0.2 * i);
    record.pocketed = pocketed[i];
    run.result.final_balls.push_back(record);
  }
  return run;
}

TEST(ShotOutcome, ReadsFirstHitCushionsBeforeItAndPocketsFromTheEvents) {
  const SceneRun run = handMadeRun(
      {contact(EventKind::Cushion, 0, -1, 2), contact(EventKind::Jaw, 0, -1, 5),
       contact(EventKind::StateChange, 0, -1, -1), contact(EventKind::BallBall, 2, 0, -1),
       contact(EventKind::Cushion, 0, -1, 1), contact(EventKind::BallBall, 0, 1, -1),
       contact(EventKind::Pocket, 2, -1, 3), contact(EventKind::Pocket, 1, -1, 0)},
      {false, true, true});
  const ShotOutcome outcome = shotOutcome(run, "cue");
  ASSERT_TRUE(outcome.first_hit.has_value());
  EXPECT_EQ(*outcome.first_hit, "2");  // the other ball of the first contact, whichever order
  EXPECT_EQ(outcome.cushions_before_first_hit, 2);  // a cushion and a jaw; the later one not
  ASSERT_EQ(outcome.pocketed.size(), 2u);
  EXPECT_EQ(outcome.pocketed[0].ball, "2");
  EXPECT_EQ(outcome.pocketed[0].pocket, 3);
  EXPECT_EQ(outcome.pocketed[1].ball, "1");
  EXPECT_EQ(outcome.pocketed[1].pocket, 0);
  EXPECT_FALSE(outcome.cue_ball_pocketed);
  EXPECT_EQ(outcome.foul, Foul::None);
  EXPECT_EQ(outcome.events, 8);
  EXPECT_EQ(outcome.cue_ball_final_m, Eigen::Vector2d(0, 0));
  EXPECT_TRUE(outcome.wasPocketed("1"));
  EXPECT_FALSE(outcome.wasPocketed("cue"));
  EXPECT_EQ(outcome.ball("2")->position_m, Eigen::Vector2d(0.2, -0.4));
  EXPECT_EQ(outcome.ball("9"), nullptr);
}

TEST(ShotOutcome, APocketedCueBallIsAFoulEvenAfterAHit) {
  const SceneRun run =
      handMadeRun({contact(EventKind::BallBall, 0, 1, -1), contact(EventKind::Pocket, 0, -1, 4)},
                  {true, false, false});
  const ShotOutcome outcome = shotOutcome(run, "cue");
  EXPECT_TRUE(outcome.cue_ball_pocketed);
  EXPECT_EQ(outcome.foul, Foul::CueBallPocketed);
  EXPECT_EQ(*outcome.first_hit, "1");
}

TEST(ShotOutcome, TouchingNoBallIsAFoulAndEveryCushionCounts) {
  const SceneRun run =
      handMadeRun({contact(EventKind::Cushion, 0, -1, 0), contact(EventKind::Cushion, 0, -1, 7),
                   contact(EventKind::BallBall, 1, 2, -1)},  // not the cue ball
                  {false, false, false});
  const ShotOutcome outcome = shotOutcome(run, "cue");
  EXPECT_FALSE(outcome.first_hit.has_value());
  EXPECT_EQ(outcome.cushions_before_first_hit, 2);
  EXPECT_EQ(outcome.foul, Foul::NoBallHit);
}

TEST(ShotOutcome, TheStruckBallNeedNotBeCalledCue) {
  const SceneRun run = handMadeRun({contact(EventKind::BallBall, 2, 1, -1)}, {false, false, false});
  EXPECT_EQ(*shotOutcome(run, "1").first_hit, "2");
  EXPECT_THROW(shotOutcome(run, "7"), std::invalid_argument);
}

TEST(ShotOutcome, AStraightFullHitOnARealTableHitsTheBallAndKeepsTheCueBallUp) {
  const Scene scene =
      sceneFromJson(nlohmann::json::parse(R"({"table": "pool-9ft", "ball_set": "pool",
        "balls": {"cue": [-0.5, 0.0], "1": [0.0, 0.0]},
        "shot": {"aim_at": "1", "speed_mps": 1.0}})"),
                    "test");
  const ShotOutcome outcome = shotOutcome(runScene(scene), "cue");
  EXPECT_EQ(outcome.first_hit.value_or("none"), "1");
  EXPECT_EQ(outcome.cushions_before_first_hit, 0);
  EXPECT_FALSE(outcome.cue_ball_pocketed);
  EXPECT_EQ(outcome.foul, Foul::None);
  // Along the x axis, by symmetry, the cue ball stays on y = 0 and ahead of where it started.
  EXPECT_EQ(outcome.cue_ball_final_m.y(), 0.0);
  EXPECT_GT(outcome.cue_ball_final_m.x(), -0.5);
}

}  // namespace
}  // namespace baize::engine
