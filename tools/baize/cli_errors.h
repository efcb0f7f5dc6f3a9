// How the baize commands report errors: one line "baize <command>: error: <message>" on stderr and
// an exit status that tells usage errors (2: a flag or input value the program or the model does
// not accept) from failures (1: a file that cannot be written, a solver that breaks down).
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <stdexcept>
#include <string>

namespace baize::tools {

// The largest count a bench flag (runs, impacts, shots) takes: a million already runs for hours,
// and a larger one is a typing slip that would exhaust memory or time.
constexpr int kMaxBenchCount = 1000000;
constexpr const char* kBenchCountAllowed = "it must lie in [1, 1000000]";

constexpr int kExitUsage = 2;
constexpr int kExitFailure = 1;

// A flag value the command refuses; the message names the flag and the value.
class UsageError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws UsageError "<flag> = <value> is not allowed: <allowed>".
[[noreturn]] void rejectFlag(const std::string& flag, double value, const std::string& allowed);
void requireFiniteFlag(const std::string& flag, double value);

// A refusal from the models ("<quantity> = <value> is not allowed: ...") restated as the user wrote
// it: "<flag> = <value> is not allowed: ... (<quantity>)". Returns the message unchanged when it
// does not start with `quantity`.
std::string namingTheFlag(const std::string& model_message, const std::string& quantity,
                          const std::string& flag);

// Runs a command's body and turns what it throws into the message and exit status above
// (std::invalid_argument, which the physics throws for inputs outside the model, counts as usage).
// Returns 0 when the body returns normally and standard output took everything it printed.
int runReportingErrors(const std::string& command, const std::function<void()>& body);

// A check for flags read into 64-bit unsigned integers (seeds), which CLI11 would otherwise take
// "-1" as 2^64 - 1 and larger values wrapped: a whole number in [0, 2^64 - 1].
CLI::Validator unsigned64();
// A check for path and text flags whose empty value would otherwise read as "not given".
CLI::Validator notEmpty();

}  // namespace baize::tools
