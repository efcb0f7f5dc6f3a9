#include "render/whole_file.h"

#include <filesystem>
#include <stdexcept>

namespace baize::render {
namespace {

// Links followed at most, as the kernel's own limit (ELOOP): a longer chain is a loop.
constexpr int kMaxLinkHops = 40;

}  // namespace

WholeFileTarget wholeFileTarget(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code error;
  WholeFileTarget target{path, false};
  // A symbolic link (or a chain of them, dangling or not) names the file to replace.
  fs::path resolved = path;
  for (int hop = 0; hop < kMaxLinkHops && fs::is_symlink(fs::symlink_status(resolved, error));
       ++hop) {
    const fs::path link = fs::read_symlink(resolved, error);
    if (error) break;
    resolved = (link.is_absolute() ? link : resolved.parent_path() / link).lexically_normal();
  }
  target.path = resolved.string();
  const fs::file_status status = fs::status(target.path, error);
  if (fs::is_directory(status)) {
    throw std::invalid_argument("'" + path +
                                "' is a directory, which is not allowed: an output must name a "
                                "file");
  }
  target.stream = fs::exists(status) && !fs::is_regular_file(status);
  return target;
}

std::string temporaryFor(const WholeFileTarget& target) { return target.path + ".tmp"; }

}  // namespace baize::render
