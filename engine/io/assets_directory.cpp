#include "engine/io/assets_directory.h"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace baize::engine {
namespace {

namespace fs = std::filesystem;

// Folders climbed from the program's own: bin/ is one below the prefix, a Python module in
// lib/python3/dist-packages/baize/ four, and tests sit a few folders deep in the build tree.
constexpr int kFoldersClimbed = 6;
// The marker that a share/baize folder is a Baize assets folder, not an unrelated one.
constexpr const char* kMarkerFolder = "tables";

// The file that holds this code: the Python module or a shared library when dladdr names one,
// the running program otherwise (for it dladdr may give only argv[0]).
std::vector<fs::path> codeFolders() {
  std::vector<fs::path> folders;
  std::error_code error;
  Dl_info info{};
  if (dladdr(reinterpret_cast<const void*>(&assetsDirectoryAbove), &info) != 0 &&
      info.dli_fname != nullptr) {
    const fs::path object = fs::canonical(info.dli_fname, error);
    if (!error) folders.push_back(object.parent_path());
  }
  const fs::path program = fs::canonical("/proc/self/exe", error);
  if (!error) folders.push_back(program.parent_path());
  return folders;
}

std::string findAssetsDirectory() {
  if (const char* named = std::getenv(kDataDirectoryVariable); named != nullptr && *named != 0) {
    std::error_code error;
    if (!fs::is_directory(fs::path(named) / kMarkerFolder, error)) {
      throw std::runtime_error(std::string("the assets folder named by ") + kDataDirectoryVariable +
                               "='" + named + "' has no " + kMarkerFolder + "/ folder");
    }
    return named;
  }
  std::string looked;
  for (const fs::path& folder : codeFolders()) {
    const std::string found = assetsDirectoryAbove(folder.string());
    if (!found.empty()) return found;
    looked += (looked.empty() ? "" : ", ") + folder.string();
  }
  throw std::runtime_error("cannot find Baize's assets (share/baize/" + std::string(kMarkerFolder) +
                           "/) above " + (looked.empty() ? "the running program" : looked) +
                           "; set " + kDataDirectoryVariable + " to the assets folder");
}

}  // namespace

std::string assetsDirectoryAbove(const std::string& start) {
  std::error_code error;
  fs::path folder = start;
  for (int climbed = 0; climbed <= kFoldersClimbed && !folder.empty(); ++climbed) {
    const fs::path candidate = folder / "share" / "baize";
    if (fs::is_directory(candidate / kMarkerFolder, error)) return candidate.string();
    if (folder == folder.parent_path()) break;
    folder = folder.parent_path();
  }
  return "";
}

std::string assetsDirectory() {
  // Found once: the program does not move while it runs. A failure is not kept, so every caller
  // sees the message.
  static std::mutex mutex;
  static std::string found;
  const std::lock_guard<std::mutex> lock(mutex);
  if (found.empty()) found = findAssetsDirectory();
  return found;
}

}  // namespace baize::engine
