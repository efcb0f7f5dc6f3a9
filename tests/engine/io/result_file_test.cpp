#include "engine/io/result_file.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

#include "engine/io/json_reader.h"
#include "engine/play/shot_outcome.h"
#include "tests/engine/error_test_support.h"

namespace baize::engine {
namespace {

std::string scenePath(const std::string& name) {
  return assetsDirectory() + "/scenes/" + name + ".json";
}

// A result as `baize simulate --json` makes it (with_recording) or as `baize batch` does.
ShotResult resultOf(const std::string& scene_name, bool with_recording) {
  const Scene scene = loadScene(scenePath(scene_name));
  return shotResult(scene, runScene(scene, with_recording), with_recording);
}

// Written as text and read back, as a file goes.
ShotResult throughText(const ShotResult& result) {
  return resultFromJson(JsonReader::parseText(resultJson(result).dump(2), "result.json"),
                        "result.json");
}

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
template <int N>
bool sameBits(const Eigen::Matrix<double, N, 1>& a, const Eigen::Matrix<double, N, 1>& b) {
  for (int i = 0; i < N; ++i) {
    if (!sameBits(a[i], b[i])) return false;
  }
  return true;
}
bool sameBits(const physics::BallState& a, const physics::BallState& b) {
  return sameBits<2>(a.position, b.position) && sameBits<3>(a.velocity, b.velocity) &&
         sameBits<3>(a.angular_velocity, b.angular_velocity);
}

// Every field of the two results equal, doubles bit for bit.
void expectSame(const ShotResult& a, const ShotResult& b) {
  EXPECT_EQ(a.source, b.source);
  EXPECT_EQ(a.line, b.line);
  EXPECT_EQ(a.id, b.id);
  EXPECT_EQ(a.scene.document, b.scene.document);
  ASSERT_EQ(a.scene.balls.size(), b.scene.balls.size());
  for (std::size_t i = 0; i < a.scene.balls.size(); ++i) {
    EXPECT_EQ(a.scene.balls[i].id, b.scene.balls[i].id);
    EXPECT_TRUE(sameBits<2>(a.scene.balls[i].position_m, b.scene.balls[i].position_m));
  }
  EXPECT_TRUE(sameBits(a.scene.shot.heading_rad, b.scene.shot.heading_rad));
  EXPECT_TRUE(sameBits(a.scene.shot.speed_mps, b.scene.shot.speed_mps));
  EXPECT_EQ(a.physics, b.physics);
  EXPECT_TRUE(sameBits(a.params.cloth.rolling_friction, b.params.cloth.rolling_friction));
  EXPECT_TRUE(sameBits(a.end_time_s, b.end_time_s));
  EXPECT_EQ(a.first_ball_hit, b.first_ball_hit);
  EXPECT_EQ(a.cushions_before_first_hit, b.cushions_before_first_hit);
  ASSERT_EQ(a.pocketed.size(), b.pocketed.size());
  for (std::size_t i = 0; i < a.pocketed.size(); ++i) {
    EXPECT_EQ(a.pocketed[i].ball, b.pocketed[i].ball);
    EXPECT_EQ(a.pocketed[i].pocket, b.pocketed[i].pocket);
  }
  EXPECT_EQ(a.foul, b.foul);
  EXPECT_EQ(a.event_count, b.event_count);
  ASSERT_EQ(a.final_positions_m.size(), b.final_positions_m.size());
  for (std::size_t i = 0; i < a.final_positions_m.size(); ++i) {
    ASSERT_EQ(a.final_positions_m[i].has_value(), b.final_positions_m[i].has_value());
    if (a.final_positions_m[i]) {
      EXPECT_TRUE(sameBits<2>(*a.final_positions_m[i], *b.final_positions_m[i]));
    }
  }
  EXPECT_EQ(a.cushion_contacts, b.cushion_contacts);
  EXPECT_EQ(a.beyond_model_range, b.beyond_model_range);
  EXPECT_EQ(a.predictions_solved, b.predictions_solved);
  EXPECT_EQ(a.predictions_skipped, b.predictions_skipped);
  ASSERT_EQ(a.trajectories.has_value(), b.trajectories.has_value());
  if (a.trajectories) {
    ASSERT_EQ(a.trajectories->size(), b.trajectories->size());
    for (std::size_t i = 0; i < a.trajectories->size(); ++i) {
      const Trajectory &p = (*a.trajectories)[i], &q = (*b.trajectories)[i];
      ASSERT_EQ(p.size(), q.size());
      for (std::size_t k = 0; k < p.size(); ++k) {
        EXPECT_TRUE(sameBits(p[k].start_time_s, q[k].start_time_s));
        EXPECT_TRUE(sameBits(p[k].state, q[k].state));
        EXPECT_EQ(p[k].pocketed, q[k].pocketed);
      }
    }
  }
  ASSERT_EQ(a.events.has_value(), b.events.has_value());
  if (a.events) {
    ASSERT_EQ(a.events->size(), b.events->size());
    for (std::size_t k = 0; k < a.events->size(); ++k) {
      const Event &e = (*a.events)[k], &f = (*b.events)[k];
      EXPECT_TRUE(sameBits(e.time_s, f.time_s));
      EXPECT_EQ(e.kind, f.kind);
      EXPECT_EQ(e.ball, f.ball);
      EXPECT_EQ(e.other, f.other);
      EXPECT_EQ(e.index, f.index);
      ASSERT_EQ(e.before.size(), f.before.size());
      ASSERT_EQ(e.after.size(), f.after.size());
      for (std::size_t j = 0; j < e.before.size(); ++j)
        EXPECT_TRUE(sameBits(e.before[j], f.before[j]));
      for (std::size_t j = 0; j < e.after.size(); ++j)
        EXPECT_TRUE(sameBits(e.after[j], f.after[j]));
    }
  }
  ASSERT_EQ(a.samples.size(), b.samples.size());
  for (std::size_t k = 0; k < a.samples.size(); ++k) {
    EXPECT_EQ(a.samples[k].ball, b.samples[k].ball);
    EXPECT_TRUE(sameBits(a.samples[k].time_s, b.samples[k].time_s));
    EXPECT_EQ(a.samples[k].pocketed, b.samples[k].pocketed);
    EXPECT_EQ(a.samples[k].pocket, b.samples[k].pocket);
    EXPECT_TRUE(sameBits(a.samples[k].fell_at_s, b.samples[k].fell_at_s));
    if (!a.samples[k].pocketed) {
      EXPECT_TRUE(sameBits(a.samples[k].state, b.samples[k].state));
    }
  }
}

TEST(ResultFile, EveryShippedSceneRoundTripsBitForBit) {
  for (const auto& file : std::filesystem::directory_iterator(assetsDirectory() + "/scenes")) {
    SCOPED_TRACE(file.path());
    const std::string name = file.path().stem().string();
    for (const bool recorded : {true, false}) {
      const ShotResult written = resultOf(name, recorded);
      const ShotResult read = throughText(written);
      expectSame(written, read);
      EXPECT_EQ(resultJson(read), resultJson(written));  // and it writes the same document again
    }
  }
}

TEST(ResultFile, ImpactsBeyondTheModelsRangeRoundTripAndMayBeAbsent) {
  const ShotResult written = resultOf("8-ball-break", false);
  ASSERT_FALSE(written.beyond_model_range.empty());  // a break's hardest cushion impacts
  EXPECT_EQ(throughText(written).beyond_model_range, written.beyond_model_range);
  nlohmann::json without = resultJson(written);
  without.erase("beyond_model_range");  // as results written before the key was
  EXPECT_TRUE(resultFromJson(without, "old.json").beyond_model_range.empty());
}

TEST(ResultFile, SamplesLineAndIdRoundTrip) {
  ShotResult result = resultOf("one-cushion-bank", true);
  result.line = 12;
  result.id = nlohmann::json{{"any", {1, "json"}}};
  ResultSample rolling;
  rolling.ball = "cue";
  rolling.time_s = 0.1;
  rolling.state = sampleTrajectory(result.params.cloth, result.trajectories->at(0), 0.1);
  ResultSample fallen;
  fallen.ball = "1";
  fallen.time_s = 1000;
  fallen.pocketed = true;
  fallen.pocket = result.pocketed.at(0).pocket;
  fallen.fell_at_s = result.events->back().time_s / 2;
  result.samples = {rolling, fallen};
  expectSame(result, throughText(result));
}

// A result of `baize simulate --json` and one of `baize batch` of the same shot: one reader, the
// same names for the same things and the same values; batch leaves out only the recording.
TEST(ResultFile, SimulateAndBatchResultsShareTheirFields) {
  const nlohmann::json simulated = resultJson(throughText(resultOf("9-ball-break", true)));
  const nlohmann::json batched = resultJson(throughText(resultOf("9-ball-break", false)));
  for (const auto& item : batched.items()) {
    ASSERT_TRUE(simulated.contains(item.key())) << item.key();
    EXPECT_EQ(simulated.at(item.key()), item.value()) << item.key();
  }
  for (const auto& item : simulated.items()) {
    if (!batched.contains(item.key())) {
      EXPECT_TRUE(item.key() == "trajectories" || item.key() == "events") << item.key();
    }
  }
}

// A table and a ball set of the scene's own are embedded: the result reads with the files gone.
TEST(ResultFile, OwnTableAndBallSetAreEmbedded) {
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("result_file_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  std::filesystem::copy_file(assetsDirectory() + "/tables/pool-9ft.json", folder / "mine.json",
                             std::filesystem::copy_options::overwrite_existing);
  std::filesystem::copy_file(assetsDirectory() + "/balls/pool.json", folder / "balls.json",
                             std::filesystem::copy_options::overwrite_existing);
  {
    std::ofstream((folder / "scene.json").string())
        << R"({"table": "mine.json", "ball_set": "balls.json",
               "balls": {"cue": [-0.6, 0], "1": [0, 0]}, "shot": {"aim_at": "1", "speed_mps": 2}})";
  }
  const Scene scene = loadScene((folder / "scene.json").string());
  const ShotResult written = shotResult(scene, runScene(scene, true), true);
  std::filesystem::remove_all(folder);
  EXPECT_TRUE(written.scene.document.at("table").is_object());
  EXPECT_TRUE(written.scene.document.at("ball_set").is_object());
  const ShotResult read = throughText(written);
  expectSame(written, read);
  EXPECT_EQ(read.scene.table.name, scene.table.name);
  EXPECT_EQ(read.scene.ball_set.radius_m, scene.ball_set.radius_m);
}

std::string refusal(const nlohmann::json& document) {
  return invalidArgumentMessage([&] { resultFromJson(document, "result.json"); });
}

TEST(ResultFile, RefusalsNameTheFileTheKeyTheValueAndWhatIsAllowed) {
  const nlohmann::json good = resultJson(resultOf("one-cushion-bank", true));
  ASSERT_EQ(good.at("pocketed").at(0).at("ball"), "1");
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  struct Case {
    std::string name;
    std::function<void(nlohmann::json&)> edit;
    std::string expected;
  };
  const std::vector<Case> cases = {
      {"missing key", [](nlohmann::json& r) { r.erase("foul"); },
       "result.json: foul is missing: it is required"},
      {"unknown key", [](nlohmann::json& r) { r["zzz"] = 1; },
       "result.json: zzz = 1 is not allowed: unknown key; the keys here are format, version"},
      {"other version", [](nlohmann::json& r) { r["version"] = 2; },
       "result.json: version = 2 is not allowed: this baize reads version 1 of the result format "
       "only"},
      {"version as text", [](nlohmann::json& r) { r["version"] = "1"; },
       "result.json: version = \"1\" is not allowed"},
      {"no version", [](nlohmann::json& r) { r.erase("version"); },
       "result.json: version is missing: it must be 1"},
      {"no format", [](nlohmann::json& r) { r.erase("format"); },
       "result.json: format is missing: it must be \"baize-result\""},
      {"other format", [](nlohmann::json& r) { r["format"] = "baize-scene"; },
       "result.json: format = \"baize-scene\" is not allowed: it must be \"baize-result\""},
      {"failed batch line",
       [](nlohmann::json& r) {
         r = {{"format", "baize-result"}, {"version", 1}, {"error", "x"}};
       },
       "result.json: error = \"x\" is not allowed: a failed batch line holds no result"},
      {"non-finite end", [&](nlohmann::json& r) { r["end_time_s"] = nan; },
       "result.json: end_time_s = nan is not allowed: it must be a finite number"},
      {"endless shot", [](nlohmann::json& r) { r["end_time_s"] = 1e300; },
       "result.json: end_time_s = 1e+300 is not allowed: a shot must end within 3600 s"},
      {"end not at the last stop",
       [](nlohmann::json& r) { r["end_time_s"] = r["end_time_s"].get<double>() + 1e-3; },
       "is not allowed: it must be when the last ball stops or falls"},
      {"speed of a rocket",
       [](nlohmann::json& r) {
         r["trajectories"]["cue"][0]["velocity_mps"] = {1e6, 0, 0};
       },
       "result.json: trajectories.cue[0].velocity_mps = [1000000.0,0,0] is not allowed: each "
       "component must be of magnitude at most 20 m/s"},
      {"infinite speed",
       [&](nlohmann::json& r) {
         r["trajectories"]["cue"][0]["velocity_mps"] = {inf, 0, 0};
       },
       "trajectories.cue[0].velocity_mps = [null,0,0] is not allowed: it must be an array of 3 "
       "finite numbers"},
      {"spin of a turbine",
       [](nlohmann::json& r) {
         r["events"][0]["after"][0]["angular_velocity_radps"] = {0, 0, 1e5};
       },
       "result.json: events[0].after[0].angular_velocity_radps = [0,0,100000.0] is not allowed: "
       "each "
       "component must be of magnitude at most 10000 rad/s"},
      {"a path not from the scene's placement",
       [](nlohmann::json& r) { r["trajectories"]["1"][0]["position_m"][0] = 0.1; },
       "result.json: trajectories.1 = [{"},
      {"piece before the strike",
       [](nlohmann::json& r) { r["trajectories"]["1"][0]["start_time_s"] = -1; },
       "result.json: trajectories.1[0].start_time_s = -1 is not allowed: it must be a finite "
       "number >= 0"},
      {"event after the end", [](nlohmann::json& r) { r["events"][1]["time_s"] = 1e3; },
       "result.json: events[1].time_s = 1000.0 is not allowed: it must lie in [0, end_time_s"},
      {"pieces out of order",
       [](nlohmann::json& r) {
         nlohmann::json& pieces = r["trajectories"]["cue"];
         pieces[0]["start_time_s"] = pieces[1]["start_time_s"].get<double>() + 1e-3;
       },
       "result.json: trajectories.cue[1].start_time_s = "},
      {"beyond-range index past the events",
       [](nlohmann::json& r) { r["beyond_model_range"] = {r["event_count"]}; },
       "result.json: beyond_model_range[0] = "},
      {"beyond-range indices out of order",
       [](nlohmann::json& r) { r["beyond_model_range"] = {3, 2}; },
       "result.json: beyond_model_range[1] = 2 is not allowed: it must be an event index"},
      {"beyond-range index as text",
       [](nlohmann::json& r) { r["beyond_model_range"] = {"3"}; },
       "result.json: beyond_model_range[0] = \"3\" is not allowed"},
      {"off the table",
       [](nlohmann::json& r) {
         r["final_positions_m"]["cue"] = {9, 0};
       },
       "result.json: final_positions_m.cue = [9,0] is not allowed: it is off the table"},
      {"a pocketed ball placed",
       [](nlohmann::json& r) {
         r["final_positions_m"]["1"] = {0, 0};
       },
       "result.json: final_positions_m.1 = [0,0] is not allowed: null: the ball is pocketed"},
      {"a ball not of the scene", [](nlohmann::json& r) { r["events"][0]["ball"] = "99"; },
       "result.json: events[0].ball = \"99\" is not allowed: one of the scene's balls: \"1\" or "
       "\"cue\""},
      {"a ball missing", [](nlohmann::json& r) { r["cushion_contacts"].erase("1"); },
       "result.json: cushion_contacts.1 is missing"},
      {"a pocket unknown", [](nlohmann::json& r) { r["pocketed"][0]["pocket"] = "middle"; },
       "result.json: pocketed[0].pocket = \"middle\" is not allowed: a pocket: \"bottom-left\""},
      {"a foul unknown", [](nlohmann::json& r) { r["foul"] = "push"; },
       "result.json: foul = \"push\" is not allowed: \"none\", \"cue ball pocketed\" or \"no ball "
       "hit\""},
      {"a second ball where none is",
       [](nlohmann::json& r) {
         for (nlohmann::json& e : r["events"]) {
           if (e["type"] == "state change") e["other"] = "1";
         }
       },
       "].other = \"1\" is not allowed: only a ball-ball event names another ball"},
      {"an unknown key in an event's state",
       [](nlohmann::json& r) { r["events"][2]["before"][0]["spin"] = 1; },
       "result.json: events[2].before[0].spin = 1 is not allowed: unknown key"},
      {"three balls in one event",
       [](nlohmann::json& r) {
         nlohmann::json& after = r["events"][0]["after"];
         after.push_back(after[0]);
         after.push_back(after[0]);
       },
       "result.json: events[0].after = [{"},
      {"a cushion beyond the table's",
       [](nlohmann::json& r) {
         for (nlohmann::json& e : r["events"]) {
           if (e["type"] == "cushion") e["index"] = 18;
         }
       },
       "].index = 18 is not allowed: it must be an integer in [0, 17]"},
      {"events miscounted", [](nlohmann::json& r) { r["event_count"] = 1; },
       "result.json: events = [{"},
      {"the scene names a file", [](nlohmann::json& r) { r["scene"]["table"] = "mine.json"; },
       "result.json: scene.table = \"mine.json\" is not allowed: a result's scene holds its table"},
      {"the scene refused", [](nlohmann::json& r) { r["scene"]["shot"]["speed_mps"] = 800; },
       "result.json: scene: shot.speed_mps = 800 is not allowed"},
      {"physics refused", [](nlohmann::json& r) { r["physics"]["max_events"] = -1; },
       "result.json: physics.max_events = -1 is not allowed"},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    nlohmann::json edited = good;
    c.edit(edited);
    EXPECT_MENTIONS(refusal(edited), c.expected);
  }
  EXPECT_EQ(
      refusal(nlohmann::json::array()).rfind("result.json: the document = [] is not allowed", 0),
      0u);
  EXPECT_MENTIONS(invalidArgumentMessage([] { loadResult("/no/such/result.json"); }),
                  "/no/such/result.json: the file cannot be opened");
}

}  // namespace
}  // namespace baize::engine
