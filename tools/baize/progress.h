// Progress of long work (stress, benches, frames, sweep, plan, check --noise, batch) and the
// commands' other notes, under one rule: progress is shown on standard error only when it is a
// terminal, as one line rewritten in place and cleared at the end, so files and pipes never get
// it; `--quiet` (every command has it) silences progress and the notes ("wrote FILE",
// "picture: FILE"), leaving the results.
#pragma once

#include <atomic>
#include <chrono>
#include <mutex>
#include <ostream>
#include <string>

namespace CLI {
class App;
}

namespace baize::tools {

// Adds --quiet to `command` and every command under it.
void addQuietFlag(CLI::App& command);
bool quiet();

// `stream`, or a stream that drops everything under --quiet: for notes that are not results.
std::ostream& note(std::ostream& stream);

class Progress {
 public:
  // `what` names the work and its unit ("frames", "shots"); `total` the units to do.
  Progress(std::string what, long total);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  // Counts `units` more done; safe from several threads. Redraws at most a few times a second.
  void advance(long units = 1);

 private:
  void draw(long done);

  std::string what_;
  long total_;
  bool shown_;  // standard error is a terminal and --quiet is not given
  std::atomic<long> done_{0};
  std::mutex drawing_;
  std::chrono::steady_clock::time_point last_drawn_{};
};

}  // namespace baize::tools
