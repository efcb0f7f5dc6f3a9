// `baize check SUITE.json [--junit FILE] [--noise N --seed S ...]`: runs a shot suite like a test
// runner (docs/positional.md): one line per case with pass/fail and the measured value behind each
// expectation, a summary "N passed, M failed", exit status 1 when a case fails.
#pragma once

namespace CLI {
class App;
}

namespace baize::tools {

class Drawing;

// `drawing` makes its pictures; null in a build without rendering (picture_commands.h).
void addCheckCommand(CLI::App& parent, const Drawing* drawing);

}  // namespace baize::tools
