#include "render/whole_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <stdexcept>

namespace baize::render {
namespace {

namespace fs = std::filesystem;

// Links followed at most, as the kernel's own limit (ELOOP): a longer chain is a loop.
constexpr int kMaxLinkHops = 40;

// Whether a path lies in /proc: /dev/stdout and /dev/fd/N lead to /proc/self/fd/N, whose link
// text ("pipe:[123]") is no path, and whose file is an open descriptor's (a pipe, or a file the
// shell opened for appending).
bool inProc(const fs::path& path) { return path.string().rfind("/proc/", 0) == 0; }

// The file a dangling or relative chain of links names: each link's text taken from the real
// folder the link lies in (not from the text of the path that reached it, which a linked folder
// and ".." would mislead). Empty when the chain leads into /proc (a descriptor: written straight).
// Throws on a loop.
std::optional<fs::path> followLinks(const fs::path& start) {
  fs::path at = start;
  for (int hop = 0; hop < kMaxLinkHops; ++hop) {
    const fs::path folder = at.has_parent_path() ? at.parent_path() : fs::path(".");
    std::error_code folder_error, link_error;
    fs::path real_folder = fs::weakly_canonical(folder, folder_error);
    if (folder_error) real_folder = folder;
    if (inProc(at) || inProc(real_folder)) return std::nullopt;
    if (!fs::is_symlink(fs::symlink_status(at, link_error))) return at;
    const fs::path link = fs::read_symlink(at, link_error);
    if (link_error) return at;
    at = link.is_absolute() ? link : real_folder / link;
  }
  throw std::invalid_argument("it is a loop of symbolic links");
}

}  // namespace

WholeFileTarget wholeFileTarget(const std::string& path) {
  std::error_code error;
  // What the kernel finds there, links followed.
  const fs::file_status status = fs::status(path, error);
  if (fs::is_directory(status)) {
    throw std::invalid_argument("it is a directory; an output must name a file");
  }
  const std::optional<fs::path> file = followLinks(path);
  if (!file || (fs::exists(status) && !fs::is_regular_file(status))) {
    // A device, a pipe, or an open descriptor (/dev/stdout): written straight, appended to.
    if (fs::is_fifo(status)) {
      // Opening a pipe that no program reads would wait forever.
      const int probe = ::open(path.c_str(), O_WRONLY | O_NONBLOCK);
      if (probe < 0 && errno == ENXIO) {
        throw std::invalid_argument("it is a named pipe that no program reads");
      }
      if (probe >= 0) ::close(probe);
    }
    return {path, true};
  }
  return {file->string(), false};
}

std::string temporaryFor(const WholeFileTarget& target) { return target.path + ".tmp"; }

}  // namespace baize::render
