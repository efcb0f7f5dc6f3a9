// Output folders: the one rule for every flag that names a folder Baize fills with files it names
// itself (--png-dir frames and case pictures, stress --failures). The folder is made if missing,
// with its parents. Files an earlier run wrote there (their names match the output's pattern) are
// removed before any work, so the folder holds this run's files only. A folder holding anything
// else is refused, so a mistyped path never deletes or mixes with a user's own files.
#pragma once

#include <string>

namespace baize::tools {

// The names an output writes: prefix + anything + suffix (e.g. "frame_" ... ".png").
struct OutputFileNames {
  std::string prefix;
  std::string suffix;

  bool match(const std::string& file_name) const;
  std::string describe() const { return prefix + "*" + suffix; }
};

// Makes `folder` ready for the output `flag` names, as above; throws UsageError naming the flag,
// the folder and the first file that is not Baize's.
void prepareOutputFolder(const std::string& flag, const std::string& folder,
                         const OutputFileNames& names);

}  // namespace baize::tools
