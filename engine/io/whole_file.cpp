#include "engine/io/whole_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace baize::engine {
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
  if (path == kStandardOutputPath) return {"/dev/stdout", true};
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

std::error_code makeParentFolders(const std::string& path) {
  const fs::path file(path);
  std::error_code error;
  if (file.has_parent_path()) fs::create_directories(file.parent_path(), error);
  return error;
}

void prepareWholeFile(const std::string& path) {
  const std::error_code error = makeParentFolders(path);
  const WholeFileTarget target = wholeFileTarget(path);
  if (target.stream) return;  // written straight: nothing to create beside it
  const std::string probe = temporaryFor(target);
  std::FILE* out = std::fopen(probe.c_str(), "wb");
  if (out == nullptr || error) {
    if (out != nullptr) std::fclose(out);
    throw std::invalid_argument("the file cannot be created there" +
                                (error ? " (" + error.message() + ")" : std::string()));
  }
  std::fclose(out);
  std::remove(probe.c_str());
}

void writeWholeFile(const std::vector<std::uint8_t>& bytes, const std::string& path) {
  const WholeFileTarget target = wholeFileTarget(path);
  const std::string written = target.stream ? target.path : temporaryFor(target);
  errno = 0;
  std::FILE* file = std::fopen(written.c_str(), target.stream ? "ab" : "wb");
  if (file == nullptr) {
    throw std::runtime_error("cannot create '" + written + "': " + std::strerror(errno));
  }
  bool ok = std::fwrite(bytes.data(), 1, bytes.size(), file) == bytes.size();
  ok = std::fflush(file) == 0 && ok;
  ok = std::fclose(file) == 0 && ok;
  std::string error = ok ? "" : "cannot write '" + written + "': " + std::strerror(errno);
  if (ok && !target.stream && std::rename(written.c_str(), target.path.c_str()) != 0) {
    error = "cannot rename '" + written + "' to '" + target.path + "': " + std::strerror(errno);
  }
  if (!error.empty()) {
    if (!target.stream) std::remove(written.c_str());
    throw std::runtime_error(error);
  }
}

}  // namespace baize::engine
