// `baize play GAME`: a frame of 9-ball, 10-ball, 8-ball or snooker between two players driven by
// the game player (or player A's shots read from a file), under execution noise, with a frame log,
// a summary and pictures (docs/games.md).
#pragma once

namespace CLI {
class App;
}

namespace baize::tools {

class Drawing;

// `drawing` makes its pictures; null in a build without rendering (picture_commands.h).
void addPlayCommand(CLI::App& parent, const Drawing* drawing);

}  // namespace baize::tools
