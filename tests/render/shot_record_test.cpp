#include "render/shot_record.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>

#include "engine/io/result_file.h"
#include "engine/io/scene_physics.h"
#include "engine/play/shot_outcome.h"

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

// A result as `baize simulate --json` (with_recording) or `baize batch` writes it, read back.
engine::ShotResult resultOf(const std::string& scene_name, bool with_recording) {
  const engine::Scene scene = engine::loadScene(scenePath(scene_name));
  const engine::ShotResult written =
      engine::shotResult(scene, engine::runScene(scene, with_recording), with_recording);
  return engine::resultFromJson(engine::resultJson(written), "result.json");
}

void expectSameShot(const ShotRecord& a, const ShotRecord& b) {
  EXPECT_EQ(a.ball_ids, b.ball_ids);
  EXPECT_EQ(a.end_time_s, b.end_time_s);
  EXPECT_EQ(a.table.name, b.table.name);
  EXPECT_EQ(a.cloth.rolling_friction, b.cloth.rolling_friction);
  ASSERT_EQ(a.events.size(), b.events.size());
  for (std::size_t k = 0; k < b.events.size(); ++k) {
    EXPECT_EQ(a.events[k].kind, b.events[k].kind);
    EXPECT_EQ(a.events[k].time_s, b.events[k].time_s);
    EXPECT_EQ(a.events[k].ball, b.events[k].ball);
    EXPECT_EQ(a.events[k].other, b.events[k].other);
    EXPECT_TRUE(a.events[k].before.empty() && a.events[k].after.empty());
  }
  ASSERT_EQ(a.trajectories.size(), b.trajectories.size());
  for (std::size_t i = 0; i < b.trajectories.size(); ++i) {
    ASSERT_EQ(a.trajectories[i].size(), b.trajectories[i].size());
    for (std::size_t k = 0; k < b.trajectories[i].size(); ++k) {
      EXPECT_EQ(a.trajectories[i][k].state.velocity, b.trajectories[i][k].state.velocity);
    }
  }
}

// A result with its trajectories (simulate) and one without (batch, simulated again) give the
// shot of their scene.
TEST(ShotRecord, ResultsGiveBackTheSameShotAsTheirScene) {
  const engine::Scene scene = engine::loadScene(scenePath("draw-shot"));
  const ShotRecord from_scene = shotRecordOf(scene, engine::runScene(scene, true));
  expectSameShot(shotRecordOf(resultOf("draw-shot", true), "result.json"), from_scene);
  expectSameShot(shotRecordOf(resultOf("draw-shot", false), "result.json"), from_scene);
}

// A result without trajectories whose scene, simulated again, is another shot is refused: the
// picture would not be of its shot.
TEST(ShotRecord, ResultFromOtherPhysicsIsRefused) {
  engine::ShotResult result = resultOf("one-cushion-bank", false);
  result.end_time_s += 1e-9;
  const std::string message = [&] {
    try {
      shotRecordOf(result, "result.json");
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  }();
  EXPECT_NE(message.find("result.json: the result holds no trajectories and its scene, simulated "
                         "again, is not its shot"),
            std::string::npos)
      << message;
  EXPECT_THROW(loadShotRecord("/no/such/result.json"), std::invalid_argument);
}

}  // namespace
}  // namespace baize::render
