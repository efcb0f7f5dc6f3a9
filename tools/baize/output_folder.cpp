#include "tools/baize/output_folder.h"

#include <filesystem>
#include <vector>

#include "tools/baize/atomic_file.h"
#include "tools/baize/cli_errors.h"

namespace baize::tools {

namespace fs = std::filesystem;

bool OutputFileNames::match(const std::string& file_name) const {
  return file_name.size() >= prefix.size() + suffix.size() &&
         file_name.compare(0, prefix.size(), prefix) == 0 &&
         file_name.compare(file_name.size() - suffix.size(), suffix.size(), suffix) == 0;
}

void prepareOutputFolder(const std::string& flag, const std::string& folder,
                         const OutputFileNames& names) {
  const std::string refused = flag + " = " + folder + " is not allowed: ";
  std::error_code error;
  fs::create_directories(folder, error);
  if (!fs::is_directory(folder)) {
    throw UsageError(refused + "it must be a folder (made if missing)" +
                     (error ? " (" + error.message() + ")" : std::string()));
  }
  // Every entry checked before any is removed: a refused folder is left as it was.
  std::vector<fs::path> earlier;
  for (const fs::directory_entry& entry : fs::directory_iterator(folder, error)) {
    const std::string name = entry.path().filename().string();
    if (!entry.is_regular_file() || !names.match(name)) {
      throw UsageError(refused + "it holds '" + name + "', which is not one of the " +
                       names.describe() + " files Baize writes there; give an empty or new folder");
    }
    earlier.push_back(entry.path());
  }
  if (error) throw UsageError(refused + "it cannot be read (" + error.message() + ")");
  for (const fs::path& file : earlier) {
    if (!fs::remove(file, error) || error) {
      throw UsageError(refused + "the earlier file '" + file.filename().string() +
                       "' cannot be removed");
    }
  }
  checkOutputPath(flag, (fs::path(folder) / (names.prefix + "probe" + names.suffix)).string());
}

}  // namespace baize::tools
