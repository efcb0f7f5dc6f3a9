// The frame log of `baize play` as JSON (docs/games.md): a game state, a shot, its outcome and the
// decision, one JSON object per shot; and a state read back from its JSON, strictly.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "engine/play/games/game_play.h"

namespace baize::engine {

nlohmann::json gameStateJson(const GameState& state);
// Throws std::invalid_argument naming `source`, the key and the value for anything gameStateJson
// would not write.
GameState gameStateFromJson(const nlohmann::json& json, const std::string& source);

nlohmann::json gameShotJson(const GameShot& shot, const physics::CueShot& stroke);
nlohmann::json shotFactsJson(const ShotFacts& facts, bool ran);
nlohmann::json decisionJson(const Decision& decision);

// One log line: {"index", "player", "state", "shot", "executed", "outcome", "decision", "next"}.
nlohmann::json playedShotJson(const PlayedShot& shot, int index);

}  // namespace baize::engine
