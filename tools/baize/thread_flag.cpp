#include "tools/baize/thread_flag.h"

#include <algorithm>
#include <string>
#include <thread>

#include "tools/baize/cli_errors.h"

namespace baize::tools {

int threadsOfFlag(int value) {
  if (value < 0 || value > kMaxThreads) {
    rejectFlag(
        "--threads", value,
        "it must lie in [0, " + std::to_string(kMaxThreads) + "] (0: the hardware concurrency)");
  }
  if (value > 0) return value;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

}  // namespace baize::tools
