#include "engine/play/shot_outcome.h"

#include <gtest/gtest.h>

#include "engine/io/json_reader.h"
#include "engine/io/table.h"

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
  EXPECT_EQ(outcome.cushion_contacts, 3);           // all of them, by any ball
  EXPECT_EQ(outcome.ball("cue")->cushion_contacts, 3);
  EXPECT_EQ(outcome.ball("2")->cushion_contacts, 0);
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

// The shipped shots show what their names say (docs/scenes.md lists them).
Scene shippedScene(const std::string& name) {
  return loadScene(assetsDirectory() + "/scenes/" + name + ".json");
}

// The cue ball's state just before its first contact with another ball, and that ball.
struct Arrival {
  physics::BallState cue;
  Eigen::Vector2d contact_m;  // the cue ball's centre at the contact
};

Arrival arrivalOf(const Scene& scene, const SceneRun& run) {
  for (const Event& e : run.result.events) {
    if (e.kind != EventKind::BallBall) continue;
    const bool cue_first = run.ball_ids.at(e.ball) == scene.cue_ball;
    if (!cue_first && run.ball_ids.at(e.other) != scene.cue_ball) continue;
    const physics::BallState cue = e.before[cue_first ? 0 : 1];
    return {cue, cue.position};
  }
  ADD_FAILURE() << "the cue ball hit no ball";
  return {};
}

// R omega along the direction of travel over the speed: 0 for a stun, 1 for natural roll, negative
// for backspin (omega_perp x z . v_hat: topspin about the axis to the left of the motion).
double spinRatio(const physics::BallState& b, double radius_m) {
  const Eigen::Vector2d v = b.velocity.head<2>();
  const Eigen::Vector2d w = b.angular_velocity.head<2>();
  return radius_m * (w.x() * v.y() - w.y() * v.x()) / -v.squaredNorm();
}

// Stun: full hit into the top-right corner; the backspin has worn off at contact, so the cue ball
// stops within a few centimetres of the contact point while the object ball drops.
TEST(ShippedScenes, StunShotArrivesWithoutSpinAndStops) {
  const Scene scene = shippedScene("stun-shot");
  const SceneRun run = runScene(scene);
  const Arrival arrival = arrivalOf(scene, run);
  const double R = scene.ball_set.radius_m;
  EXPECT_LT(std::abs(spinRatio(arrival.cue, R)), 0.05);
  const ShotOutcome outcome = shotOutcome(run, "cue");
  EXPECT_TRUE(outcome.wasPocketed("1"));
  EXPECT_LT((outcome.cue_ball_final_m - arrival.contact_m).norm(), 0.03);
}

// Draw: the cue ball still has backspin at contact and comes back towards where it started.
TEST(ShippedScenes, DrawShotArrivesWithBackspinAndComesBack) {
  const Scene scene = shippedScene("draw-shot");
  const SceneRun run = runScene(scene);
  const Arrival arrival = arrivalOf(scene, run);
  EXPECT_LT(spinRatio(arrival.cue, scene.ball_set.radius_m), -0.3);
  const ShotOutcome outcome = shotOutcome(run, "cue");
  EXPECT_TRUE(outcome.wasPocketed("1"));
  const Eigen::Vector2d along = arrival.cue.velocity.head<2>().normalized();
  EXPECT_LT((outcome.cue_ball_final_m - arrival.contact_m).dot(along), -0.1);
}

// Follow: the cue ball rolls into the object ball and follows it forward.
TEST(ShippedScenes, FollowShotArrivesRollingAndFollows) {
  const Scene scene = shippedScene("follow-shot");
  const SceneRun run = runScene(scene);
  const Arrival arrival = arrivalOf(scene, run);
  EXPECT_NEAR(spinRatio(arrival.cue, scene.ball_set.radius_m), 1.0, 1e-9);
  const ShotOutcome outcome = shotOutcome(run, "cue");
  EXPECT_TRUE(outcome.wasPocketed("1"));
  const Eigen::Vector2d along = arrival.cue.velocity.head<2>().normalized();
  EXPECT_GT((outcome.cue_ball_final_m - arrival.contact_m).dot(along), 0.1);
}

// One-cushion bank: the 1 ball goes off one cushion, across the table, into the top-middle pocket.
TEST(ShippedScenes, OneCushionBankDropsTheBallAfterOneCushion) {
  const SceneRun run = runScene(shippedScene("one-cushion-bank"));
  const ShotOutcome outcome = shotOutcome(run, "cue");
  EXPECT_EQ(outcome.first_hit.value_or("none"), "1");
  ASSERT_EQ(outcome.pocketed.size(), 1u);
  EXPECT_EQ(outcome.pocketed[0].ball, "1");
  EXPECT_EQ(pocketNames().at(outcome.pocketed[0].pocket), "top-middle");
  EXPECT_EQ(outcome.ball("1")->cushion_contacts, 1);
  EXPECT_EQ(outcome.foul, Foul::None);
}

// Three-cushion bank: the cue ball goes round three cushions before it meets the 1 ball.
TEST(ShippedScenes, ThreeCushionBankTakesThreeCushionsBeforeTheBall) {
  const ShotOutcome outcome = shotOutcome(runScene(shippedScene("three-cushion-bank")), "cue");
  EXPECT_EQ(outcome.first_hit.value_or("none"), "1");
  EXPECT_EQ(outcome.cushions_before_first_hit, 3);
}

// Heavy sidespin: straight at the top cushion with running side; the side throws the rebound off
// the straight line into the 1 ball, which the same stroke without side misses.
TEST(ShippedScenes, HeavySidespinSendsTheReboundIntoTheBall) {
  Scene scene = shippedScene("heavy-sidespin");
  const ShotOutcome with_side = shotOutcome(runScene(scene), "cue");
  EXPECT_EQ(with_side.first_hit.value_or("none"), "1");
  EXPECT_EQ(with_side.cushions_before_first_hit, 1);
  scene.shot.side_offset = 0;
  const ShotOutcome without_side = shotOutcome(runScene(scene), "cue");
  EXPECT_FALSE(without_side.first_hit.has_value());
}

}  // namespace
}  // namespace baize::engine
