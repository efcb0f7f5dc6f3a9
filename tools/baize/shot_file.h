// Player A's shots for `baize play --shots FILE`: one JSON object per line, read strictly before
// play, then turned into shots one by one against the state of the frame (docs/games.md).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/io/table.h"
#include "engine/play/games/game_setup.h"

namespace baize::tools {

struct ShotLine {
  int line = 0;  // 1-based, for messages
  nlohmann::json json;
};

// Reads and checks every line's keys and types (blank lines skipped). Throws std::invalid_argument
// naming the file, the line and the key.
std::vector<ShotLine> readShotFile(const std::string& path);

// The shot a line asks for in `state`. Throws std::invalid_argument naming the file and line for a
// place the rules refuse (not in hand, outside the allowed area, on a ball), a missing place when
// the cue ball is in hand, or an aim at a ball not on the table.
engine::GameShot shotFromLine(const ShotLine& line, const std::string& path,
                              const engine::GameState& state, const engine::GameSetup& setup);

}  // namespace baize::tools
