// "-" as an output path means standard output, for every output flag. The file then arrives
// there alone: the command's report lines go to standard error instead, and two outputs cannot
// share standard output.
#pragma once

#include <iosfwd>
#include <streambuf>
#include <string>
#include <vector>

namespace baize::tools {

// The output flags of the command line `words` (without the program name) given "-"
// ("--json -" or "--json=-"). Throws UsageError naming both when more than one is.
std::vector<std::string> outputFlagsOnStandardOutput(const std::vector<std::string>& words);

// While it lives, and when `flags` is not empty, what the commands print to std::cout goes to
// standard error (the file written to "-" opens standard output itself).
class ReportsToStandardError {
 public:
  explicit ReportsToStandardError(const std::vector<std::string>& flags);
  ~ReportsToStandardError();
  ReportsToStandardError(const ReportsToStandardError&) = delete;
  ReportsToStandardError& operator=(const ReportsToStandardError&) = delete;

 private:
  std::streambuf* saved_ = nullptr;
};

}  // namespace baize::tools
