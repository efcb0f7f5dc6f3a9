#include "render/shot_record.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>

#include "engine/io/scene_physics.h"

namespace baize::render {
namespace {

std::string scenePath(const std::string& name) {
  return engine::assetsDirectory() + "/scenes/" + name + ".json";
}

TEST(ShotRecord, SceneIsSimulatedWithTrajectoriesForEveryBall) {
  const ShotRecord shot = loadShotRecord(scenePath("one-cushion-bank"));
  const engine::Scene scene = engine::loadScene(scenePath("one-cushion-bank"));
  ASSERT_EQ(shot.ball_ids.size(), scene.balls.size());
  ASSERT_EQ(shot.trajectories.size(), scene.balls.size());
  for (std::size_t i = 0; i < scene.balls.size(); ++i) {
    EXPECT_EQ(shot.ball_ids[i], scene.balls[i].id);
    EXPECT_EQ(shot.trajectories[i].front().state.position, scene.balls[i].position_m);
  }
  EXPECT_GT(shot.end_time_s, 0);
  EXPECT_EQ(shot.cloth.radius_m, scene.ball_set.radius_m);
}

// A result document as `baize simulate --json` writes it, reduced to what the renderer reads.
nlohmann::json resultOf(const std::string& scene_name) {
  const engine::Scene scene = engine::loadScene(scenePath(scene_name));
  const engine::SceneRun run = engine::runScene(scene, true);
  nlohmann::json out;
  out["scene"] = scenePath(scene_name);
  out["end_time_s"] = run.result.end_time_s;
  out["physics"] =
      engine::physicsJson(engine::simulationParamsFor(scene), engine::cueStrikeParamsFor(scene));
  for (std::size_t i = 0; i < run.ball_ids.size(); ++i) {
    out["final"].push_back({{"id", run.ball_ids[i]}});
    for (const engine::TrajectoryPiece& q : run.result.trajectories[i]) {
      const physics::BallState& s = q.state;
      out["trajectories"][run.ball_ids[i]].push_back(
          {{"start_time_s", q.start_time_s},
           {"pocketed", q.pocketed},
           {"position_m", {s.position.x(), s.position.y()}},
           {"velocity_mps", {s.velocity.x(), s.velocity.y(), s.velocity.z()}},
           {"angular_velocity_radps",
            {s.angular_velocity.x(), s.angular_velocity.y(), s.angular_velocity.z()}}});
    }
  }
  for (const engine::Event& e : run.result.events) {
    nlohmann::json event = {{"time_s", e.time_s},
                            {"type", engine::eventKindName(e.kind)},
                            {"ball", run.ball_ids[e.ball]}};
    if (e.other >= 0) event["other"] = run.ball_ids[e.other];
    if (e.index >= 0) event["index"] = e.index;
    out["events"].push_back(event);
  }
  return out;
}

TEST(ShotRecord, ResultGivesBackTheSameShotAsItsScene) {
  const ShotRecord from_result = shotRecordFromResultJson(resultOf("draw-shot"), "result.json");
  const engine::Scene scene = engine::loadScene(scenePath("draw-shot"));
  const ShotRecord from_scene = shotRecordOf(scene, engine::runScene(scene, true));
  EXPECT_EQ(from_result.ball_ids, from_scene.ball_ids);
  EXPECT_EQ(from_result.end_time_s, from_scene.end_time_s);
  ASSERT_EQ(from_result.events.size(), from_scene.events.size());
  for (std::size_t k = 0; k < from_scene.events.size(); ++k) {
    EXPECT_EQ(from_result.events[k].kind, from_scene.events[k].kind);
    EXPECT_EQ(from_result.events[k].time_s, from_scene.events[k].time_s);
    EXPECT_EQ(from_result.events[k].ball, from_scene.events[k].ball);
    EXPECT_EQ(from_result.events[k].other, from_scene.events[k].other);
  }
  ASSERT_EQ(from_result.trajectories.size(), from_scene.trajectories.size());
  for (std::size_t i = 0; i < from_scene.trajectories.size(); ++i) {
    ASSERT_EQ(from_result.trajectories[i].size(), from_scene.trajectories[i].size());
    for (std::size_t k = 0; k < from_scene.trajectories[i].size(); ++k) {
      EXPECT_EQ(from_result.trajectories[i][k].state.velocity,
                from_scene.trajectories[i][k].state.velocity);
    }
  }
}

std::string messageOf(const nlohmann::json& result) {
  try {
    shotRecordFromResultJson(result, "result.json");
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(ShotRecord, MalformedResultsAreRefusedNamingTheKey) {
  nlohmann::json no_final = resultOf("stun-shot");
  no_final.erase("final");
  EXPECT_NE(messageOf(no_final).find("final"), std::string::npos);

  nlohmann::json bad_time = resultOf("stun-shot");
  bad_time["trajectories"]["cue"][0]["start_time_s"] = "soon";
  const std::string message = messageOf(bad_time);
  EXPECT_NE(message.find("trajectories.cue[0].start_time_s"), std::string::npos) << message;

  nlohmann::json unknown_ball = resultOf("stun-shot");
  unknown_ball["events"][0]["ball"] = "99";
  EXPECT_NE(messageOf(unknown_ball).find("events[0].ball"), std::string::npos);

  EXPECT_THROW(loadShotRecord("/no/such/result.json"), std::invalid_argument);
}

// end_time_s is when the last ball stops or falls, which the last pieces of the paths fix: every
// shipped scene's result passes, and an end moved away from that instant beyond the slack does not.
TEST(ShotRecord, EndTimeMustBeWhenTheLastBallStopsOrFalls) {
  const std::string scenes = engine::assetsDirectory() + "/scenes";
  for (const auto& file : std::filesystem::directory_iterator(scenes)) {
    const nlohmann::json result = resultOf(file.path().stem().string());
    EXPECT_EQ(messageOf(result), "") << file.path();
  }
  const nlohmann::json result = resultOf("one-cushion-bank");  // its object ball is pocketed
  const double end_s = result["end_time_s"].get<double>();
  for (double edited : {1e300, 2 * end_s, end_s + 2e-6, end_s - 2e-6, 0.5 * end_s}) {
    nlohmann::json changed = result;
    changed["end_time_s"] = edited;
    const std::string message = messageOf(changed);
    EXPECT_NE(message.find("end_time_s: value"), std::string::npos) << edited << ": " << message;
    EXPECT_NE(message.find("when the last ball stops or falls"), std::string::npos) << message;
  }
  nlohmann::json within = result;
  within["end_time_s"] = end_s + 0.5e-6;  // within the slack of rounding
  EXPECT_EQ(messageOf(within), "");
}

}  // namespace
}  // namespace baize::render
