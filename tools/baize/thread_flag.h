// The --threads flag, the same in every command that runs shots on threads of its own: a count in
// [0, kMaxThreads], 0 (the default) for the hardware concurrency. The results never depend on it.
#pragma once

namespace baize::tools {

// More threads than this is a typo, not a machine.
constexpr int kMaxThreads = 1024;

// The help text of the flag.
constexpr const char* kThreadsHelp =
    "threads to run shots on, 0 (default) for the hardware concurrency; the results do not depend "
    "on it";

// The threads `value` of --threads asks for; throws UsageError naming the flag and its value
// outside [0, kMaxThreads].
int threadsOfFlag(int value);

}  // namespace baize::tools
