#include "engine/play/model_range.h"

#include <gtest/gtest.h>

#include <fstream>

#include "engine/io/assets_directory.h"
#include "engine/io/json_reader.h"
#include "engine/io/table.h"
#include "engine/play/shot_outcome.h"
#include "tests/engine/error_test_support.h"

namespace baize::engine {
namespace {

nlohmann::json sceneDocument(const std::string& name) {
  const std::string path = assetsDirectory() + "/scenes/" + name + ".json";
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

// The shipped scene with physics.cushion.valid_normal_speed_mps set to `limit`.
Scene withLimit(const std::string& name, const nlohmann::json& limit) {
  nlohmann::json document = sceneDocument(name);
  document["physics"]["cushion"]["valid_normal_speed_mps"] = limit;
  return sceneFromJson(document, name + ".json");
}

// The normal speeds worked out here from the table's own geometry (a straight cushion's inward
// normal, or the jaw's centre to the ball), apart from impactNormalSpeedMps: index -> speed.
std::vector<std::pair<long, double>> normalSpeeds(const Scene& scene, const SceneRun& run) {
  const TableGeometry& table = cachedGeometryOf(scene.table);
  std::vector<std::pair<long, double>> speeds;
  for (std::size_t i = 0; i < run.result.events.size(); ++i) {
    const Event& e = run.result.events[i];
    if (e.kind != EventKind::Cushion && e.kind != EventKind::Jaw) continue;
    const Eigen::Vector2d v = e.before[0].velocity.head<2>();
    const Eigen::Vector2d normal =
        e.kind == EventKind::Cushion
            ? table.cushions.at(e.index).inward_normal
            : (e.before[0].position - table.jaws.at(e.index).centre_m).normalized();
    speeds.push_back({static_cast<long>(i), -v.dot(normal)});
  }
  return speeds;
}

std::vector<long> above(const std::vector<std::pair<long, double>>& speeds, double limit_mps) {
  std::vector<long> indices;
  for (const auto& [index, speed] : speeds) {
    if (speed > limit_mps) indices.push_back(index);
  }
  return indices;
}

TEST(ModelRange, ABreakReportsItsHardImpactsByEventIndex) {
  const Scene scene = loadScene(assetsDirectory() + "/scenes/8-ball-break.json");
  const SceneRun run = runScene(scene);
  const auto speeds = normalSpeeds(scene, run);
  const std::vector<long> expected = above(speeds, kRigidCushionValidNormalSpeedMps);
  ASSERT_FALSE(expected.empty());  // a break drives balls into cushions above 2.5 m/s
  EXPECT_LT(expected.size(), speeds.size());  // and others below it
  EXPECT_EQ(impactsBeyondModelRange(scene, run), expected);
  for (const auto& [index, speed] : speeds) {
    EXPECT_NEAR(impactNormalSpeedMps(cachedGeometryOf(scene.table), run.result.events[index]),
                speed, 1e-12);
  }
}

TEST(ModelRange, ASoftShotReportsNone) {
  const Scene scene = loadScene(assetsDirectory() + "/scenes/heavy-sidespin.json");
  const SceneRun run = runScene(scene);
  const auto speeds = normalSpeeds(scene, run);
  ASSERT_FALSE(speeds.empty());  // it does hit cushions, below the range's limit
  EXPECT_TRUE(above(speeds, kRigidCushionValidNormalSpeedMps).empty());
  EXPECT_TRUE(impactsBeyondModelRange(scene, run).empty());
  EXPECT_TRUE(shotResult(scene, run, false).beyond_model_range.empty());
}

// A table file may carry its own limit (its cushion.valid_normal_speed_mps); a scene's still wins.
TEST(ModelRange, ATableMayCarryItsOwnLimit) {
  nlohmann::json document = sceneDocument("heavy-sidespin");
  nlohmann::json table = JsonReader::parseFile(assetsDirectory() + "/tables/" +
                                               document["table"].get<std::string>() + ".json");
  table["cushion"]["valid_normal_speed_mps"] = 0.05;
  document["table"] = table;
  const Scene low = sceneFromJson(document, "low.json");
  EXPECT_EQ(validNormalSpeedFor(low), 0.05);
  EXPECT_FALSE(impactsBeyondModelRange(low, runScene(low)).empty());
  document["physics"]["cushion"]["valid_normal_speed_mps"] = 3.0;
  EXPECT_EQ(validNormalSpeedFor(sceneFromJson(document, "high.json")), 3.0);
}

TEST(ModelRange, TheLimitChangesTheCountAndNotTheShot) {
  const Scene plain = loadScene(assetsDirectory() + "/scenes/heavy-sidespin.json");
  const Scene low = withLimit("heavy-sidespin", 0.05);
  EXPECT_EQ(validNormalSpeedFor(plain), kRigidCushionValidNormalSpeedMps);
  EXPECT_EQ(validNormalSpeedFor(low), 0.05);
  const SceneRun plain_run = runScene(plain);
  const SceneRun low_run = runScene(low);
  ASSERT_EQ(plain_run.result.events.size(), low_run.result.events.size());
  EXPECT_EQ(plain_run.result.end_time_s, low_run.result.end_time_s);
  const std::vector<long> expected = above(normalSpeeds(low, low_run), 0.05);
  ASSERT_FALSE(expected.empty());
  EXPECT_EQ(shotResult(low, low_run, false).beyond_model_range, expected);

  const Scene high = withLimit("8-ball-break", 100.0);
  EXPECT_TRUE(impactsBeyondModelRange(high, runScene(high)).empty());
}

TEST(ModelRange, BadLimitsAreRefusedNamingTheKey) {
  for (const nlohmann::json& bad : {nlohmann::json(0), nlohmann::json(-1.5),
                                    nlohmann::json("fast"), nlohmann::json(nullptr)}) {
    SCOPED_TRACE(bad.dump());
    const std::string message = invalidArgumentMessage([&] { withLimit("stun-shot", bad); });
    EXPECT_NE(message.find("stun-shot.json: physics.cushion.valid_normal_speed_mps = "),
              std::string::npos)
        << message;
  }
  // The model's own keys are still checked beside it.
  nlohmann::json document = sceneDocument("stun-shot");
  document["physics"]["cushion"] = {{"valid_normal_speed_mps", 3.0}, {"zzz", 1}};
  EXPECT_NE(invalidArgumentMessage([&] { sceneFromJson(document, "s.json"); })
                .find("physics.cushion.zzz"),
            std::string::npos);
}

TEST(ModelRange, OnlyCushionAndJawEventsHaveANormalSpeed) {
  Event e;
  e.kind = EventKind::BallBall;
  const Scene scene = loadScene(assetsDirectory() + "/scenes/stun-shot.json");
  EXPECT_NE(invalidArgumentMessage([&] { impactNormalSpeedMps(cachedGeometryOf(scene.table), e); })
                .find("only cushion and jaw events"),
            std::string::npos);
}

}  // namespace
}  // namespace baize::engine
