#include "tools/baize/shot_file.h"

#include <cmath>
#include <fstream>
#include <stdexcept>

#include "engine/io/json_reader.h"
#include "engine/play/games/game_rules.h"

namespace baize::tools {
namespace {

constexpr double kDegToRad = M_PI / 180;

std::string sourceOf(const std::string& path, int line) {
  return path + " line " + std::to_string(line);
}

void checkLine(const engine::JsonReader& r) {
  r.requireKeys({"shot"}, {"place", "call", "pocket", "push_out"});
  const engine::JsonReader shot = r.object("shot");
  shot.requireKeys({"speed_mps"}, {"aim_at", "heading_deg", "side", "height", "elevation_deg"});
  if (shot.has("aim_at") == shot.has("heading_deg")) {
    shot.reject(shot.has("aim_at") ? "heading_deg" : "aim_at",
                "a shot is aimed either at a ball (aim_at) or along a heading (heading_deg), not "
                "both and not neither");
  }
  shot.positiveNumber("speed_mps");
  for (const char* key : {"heading_deg", "side", "height", "elevation_deg"}) {
    if (shot.has(key)) shot.finiteNumber(key);
  }
  if (shot.has("aim_at")) shot.text("aim_at");
  if (r.has("place")) r.point("place");
  if (r.has("call")) r.text("call");
  if (r.has("pocket")) r.text("pocket");
  if (r.has("push_out")) r.boolean("push_out");
}

int pocketNamed(const engine::JsonReader& r) {
  const std::vector<std::string>& names = engine::pocketNames();
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (r.text("pocket") == names[i]) return static_cast<int>(i);
  }
  r.reject("pocket", "a pocket name: bottom-left, bottom-middle, bottom-right, top-right, "
                     "top-middle or top-left");
}

}  // namespace

std::vector<ShotLine> readShotFile(const std::string& path) {
  const std::string text = engine::JsonReader::readTextFile(path);
  std::vector<ShotLine> lines;
  std::size_t start = 0;
  for (int number = 1; start < text.size(); ++number) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    const std::string line = text.substr(start, end - start);
    start = end + 1;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::string source = sourceOf(path, number);
    nlohmann::json json = engine::JsonReader::parseText(line, source, "a JSON object per line");
    if (!json.is_object()) {
      throw std::invalid_argument(source + " is not allowed: each line must be a JSON object");
    }
    checkLine(engine::JsonReader(json, source));
    lines.push_back({number, std::move(json)});
  }
  return lines;
}

engine::GameShot shotFromLine(const ShotLine& line, const std::string& path,
                              const engine::GameState& state, const engine::GameSetup& setup) {
  const engine::JsonReader r(line.json, sourceOf(path, line.line));
  const engine::Table& table = setup.scene.table;
  engine::GameShot shot;
  shot.kind = "file";
  if (r.has("place")) {
    const std::string refusal =
        engine::placementRefusal(state, r.point("place"), table, setup.scene.ball_set.radius_m);
    if (!refusal.empty()) r.reject("place", "a place from hand the rules allow: " + refusal);
    shot.place = r.point("place");
  } else if (state.in_hand != engine::CueBallInHand::No) {
    r.reject("shot", std::string("a line with \"place\": the cue ball is in hand (") +
                         engine::inHandName(state.in_hand) + ")");
  }
  const engine::JsonReader s = r.object("shot");
  shot.shot.speed_mps = s.positiveNumber("speed_mps");
  shot.shot.side_offset = s.has("side") ? s.finiteNumber("side") : 0;
  shot.shot.height_offset = s.has("height") ? s.finiteNumber("height") : 0;
  shot.shot.elevation_rad = s.has("elevation_deg") ? s.finiteNumber("elevation_deg") * kDegToRad : 0;
  const Eigen::Vector2d cue = shot.place ? *shot.place : state.balls.front().position_m;
  if (s.has("aim_at")) {
    const engine::PlacedBall* target = state.ball(s.text("aim_at"));
    if (target == nullptr || target->id == "cue") s.reject("aim_at", "a ball on the table");
    const Eigen::Vector2d to = target->position_m - cue;
    shot.shot.heading_rad = std::atan2(to.y(), to.x());
  } else {
    shot.shot.heading_rad = s.finiteNumber("heading_deg") * kDegToRad;
  }
  try {
    physics::validateCueShot(shot.shot);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(r.source() + ": shot is not allowed: " + e.what());
  }
  if (r.has("call")) shot.call.ball = r.text("call");
  if (r.has("pocket")) shot.call.pocket = pocketNamed(r);
  if (r.has("push_out")) shot.call.push_out = r.boolean("push_out");
  return shot;
}

}  // namespace baize::tools
