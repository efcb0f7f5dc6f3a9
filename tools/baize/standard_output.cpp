#include "tools/baize/standard_output.h"

#include <array>
#include <iostream>

#include "engine/io/whole_file.h"
#include "tools/baize/cli_errors.h"

namespace baize::tools {
namespace {

// Every flag whose value is an output file.
constexpr std::array<const char*, 6> kOutputFileFlags = {"--json", "--csv", "--junit", "--png",
                                                         "--gif",  "--log"};

}  // namespace

std::vector<std::string> outputFlagsOnStandardOutput(const std::vector<std::string>& words) {
  const std::string dash = engine::kStandardOutputPath;
  std::vector<std::string> found;
  for (std::size_t i = 0; i < words.size(); ++i) {
    for (const std::string flag : kOutputFileFlags) {
      const bool separate = words[i] == flag && i + 1 < words.size() && words[i + 1] == dash;
      if (separate || words[i] == flag + "=" + dash) found.push_back(flag);
    }
  }
  if (found.size() > 1) {
    throw UsageError(found[0] + " - and " + found[1] +
                     " - both name standard output; at most one output can go there");
  }
  return found;
}

ReportsToStandardError::ReportsToStandardError(const std::vector<std::string>& flags) {
  if (!flags.empty()) saved_ = std::cout.rdbuf(std::cerr.rdbuf());
}

ReportsToStandardError::~ReportsToStandardError() {
  if (saved_ != nullptr) {
    std::cout.flush();
    std::cout.rdbuf(saved_);
  }
}

}  // namespace baize::tools
