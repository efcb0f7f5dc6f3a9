#include "engine/play/games/game_log.h"

#include <cmath>

#include "engine/io/json_reader.h"

namespace baize::engine {
namespace {

constexpr double kRadToDeg = 180 / M_PI;

template <typename Enum, typename Name>
Enum enumNamed(const JsonReader& reader, const std::string& key, std::initializer_list<Enum> all,
               Name name) {
  const std::string text = reader.text(key);
  std::string allowed;
  for (Enum e : all) {
    if (text == name(e)) return e;
    allowed += (allowed.empty() ? "" : ", ") + std::string(name(e));
  }
  reader.reject(key, "one of " + allowed);
}

std::array<int, 2> intPair(const JsonReader& reader, const std::string& key) {
  const std::vector<double> v = reader.finiteNumbers(key, 2);
  for (double x : v) {
    if (x != std::floor(x)) reader.reject(key, "two whole numbers");
  }
  return {static_cast<int>(v[0]), static_cast<int>(v[1])};
}

}  // namespace

nlohmann::json gameStateJson(const GameState& s) {
  nlohmann::json balls = nlohmann::json::array();
  for (const PlacedBall& b : s.balls) {
    balls.push_back({{"id", b.id}, {"at_m", {b.position_m.x(), b.position_m.y()}}});
  }
  return {{"game", gameName(s.game)},
          {"balls", balls},
          {"player", s.player},
          {"in_hand", inHandName(s.in_hand)},
          {"break_shot", s.break_shot},
          {"push_out_available", s.push_out_available},
          {"consecutive_fouls", {s.consecutive_fouls[0], s.consecutive_fouls[1]}},
          {"groups", {groupName(s.groups[0]), groupName(s.groups[1])}},
          {"score", {s.score[0], s.score[1]}},
          {"ball_on", s.ball_on},
          {"frame_over", s.frame_over},
          {"winner", s.winner},
          {"shots", s.shots}};
}

GameState gameStateFromJson(const nlohmann::json& json, const std::string& source) {
  const JsonReader r(json, source);
  r.requireExactKeys({"game", "balls", "player", "in_hand", "break_shot", "push_out_available",
                      "consecutive_fouls", "groups", "score", "ball_on", "frame_over", "winner",
                      "shots"});
  GameState s;
  s.game = enumNamed(r, "game", {Game::NineBall, Game::TenBall, Game::EightBall, Game::Snooker},
                     gameName);
  for (const JsonReader& b : r.objectArray("balls")) {
    b.requireExactKeys({"id", "at_m"});
    s.balls.push_back({b.text("id"), b.point("at_m")});
  }
  s.player = r.integer("player", 0, 1);
  s.in_hand = enumNamed(r, "in_hand",
                        {CueBallInHand::No, CueBallInHand::BehindHeadString,
                         CueBallInHand::Anywhere, CueBallInHand::InD},
                        inHandName);
  s.break_shot = r.boolean("break_shot");
  s.push_out_available = r.boolean("push_out_available");
  s.consecutive_fouls = intPair(r, "consecutive_fouls");
  const nlohmann::json& groups = json.at("groups");
  if (!groups.is_array() || groups.size() != 2) r.reject("groups", "two group names");
  for (int p = 0; p < 2; ++p) {
    const nlohmann::json wrapped = {{"group", groups[p]}};  // the reader keeps a reference
    const JsonReader g(wrapped, source, r.keyPath("groups"));
    s.groups[p] = enumNamed(g, "group", {Group::None, Group::Solids, Group::Stripes}, groupName);
  }
  s.score = intPair(r, "score");
  if (!json.at("ball_on").is_string()) r.reject("ball_on", "a string");
  s.ball_on = json.at("ball_on").get<std::string>();
  s.frame_over = r.boolean("frame_over");
  s.winner = r.integer("winner", -1, 1);
  s.shots = r.integer("shots", 0, 1000000);
  return s;
}

nlohmann::json gameShotJson(const GameShot& shot, const physics::CueShot& stroke) {
  nlohmann::json j = {{"kind", shot.kind},
                      {"heading_deg", stroke.heading_rad * kRadToDeg},
                      {"speed_mps", stroke.speed_mps},
                      {"side", stroke.side_offset},
                      {"height", stroke.height_offset},
                      {"elevation_deg", stroke.elevation_rad * kRadToDeg}};
  if (shot.place) j["place_m"] = {shot.place->x(), shot.place->y()};
  if (!shot.call.ball.empty()) j["call"] = shot.call.ball;
  if (shot.call.pocket >= 0) j["pocket"] = pocketNames().at(shot.call.pocket);
  if (shot.call.push_out) j["push_out"] = true;
  return j;
}

nlohmann::json shotFactsJson(const ShotFacts& facts, bool ran) {
  nlohmann::json pocketed = nlohmann::json::array();
  for (const PocketedBall& p : facts.pocketed) {
    pocketed.push_back({{"ball", p.ball}, {"pocket", pocketNames().at(p.pocket)}});
  }
  return {{"ran", ran},
          {"first_hit", facts.first_hit ? nlohmann::json(*facts.first_hit) : nlohmann::json()},
          {"pocketed", pocketed},
          {"cushion_after_first_hit", facts.cushion_after_first_hit},
          {"object_balls_to_cushion", facts.object_balls_to_cushion}};
}

nlohmann::json decisionJson(const Decision& d) {
  return {{"foul", gameFoulName(d.foul)}, {"rule", d.rule},
          {"turn_passes", d.turn_passes}, {"frame_over", d.frame_over},
          {"winner", d.winner},           {"respotted", d.respotted},
          {"points", d.points},           {"penalty", d.penalty}};
}

nlohmann::json playedShotJson(const PlayedShot& shot, int index) {
  return {{"index", index},
          {"player", shot.state.player},
          {"state", gameStateJson(shot.state)},
          {"shot", gameShotJson(shot.intended, shot.intended.shot)},
          {"executed", gameShotJson(shot.intended, shot.executed)},
          {"outcome", shotFactsJson(shot.facts, shot.ran)},
          {"decision", decisionJson(shot.decision)},
          {"next", gameStateJson(shot.next)}};
}

}  // namespace baize::engine
