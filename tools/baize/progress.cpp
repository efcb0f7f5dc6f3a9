#include "tools/baize/progress.h"

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <iostream>
#include <streambuf>

namespace baize::tools {
namespace {

// Redraws at most this often: often enough to look alive, rarely enough to cost nothing.
constexpr std::chrono::milliseconds kRedrawInterval{200};

bool& quietFlag() {
  static bool quiet = false;
  return quiet;
}

class NullBuffer : public std::streambuf {
 protected:
  int overflow(int c) override { return traits_type::not_eof(c); }
  std::streamsize xsputn(const char*, std::streamsize n) override { return n; }
};

}  // namespace

void addQuietFlag(CLI::App& command) {
  for (CLI::App* sub : command.get_subcommands({})) addQuietFlag(*sub);
  if (command.get_parent() == nullptr) return;  // "baize --quiet" alone would do nothing
  command.add_flag("--quiet", quietFlag(),
                   "no progress and no notes (\"wrote FILE\"): only the results");
}

bool quiet() { return quietFlag(); }

std::ostream& note(std::ostream& stream) {
  static NullBuffer nothing;
  static std::ostream dropped(&nothing);
  return quiet() ? dropped : stream;
}

Progress::Progress(std::string what, long total)
    : what_(std::move(what)), total_(total), shown_(!quiet() && ::isatty(STDERR_FILENO) == 1) {}

Progress::~Progress() {
  if (shown_) std::cerr << "\r\033[K" << std::flush;  // the line cleared: the results stay alone
}

void Progress::advance(long units) {
  const long done = done_.fetch_add(units) + units;
  if (!shown_) return;
  std::unique_lock<std::mutex> lock(drawing_, std::try_to_lock);
  if (!lock.owns_lock()) return;  // another thread is drawing
  const auto now = std::chrono::steady_clock::now();
  if (now - last_drawn_ < kRedrawInterval && (total_ <= 0 || done < total_)) return;
  last_drawn_ = now;
  draw(done);
}

void Progress::draw(long done) {
  std::cerr << "\r\033[K" << done;
  if (total_ > 0) std::cerr << " / " << total_;
  std::cerr << ' ' << what_;
  if (total_ > 0) std::cerr << " (" << done * 100 / total_ << " %)";
  std::cerr << std::flush;
}

}  // namespace baize::tools
