#include "tools/baize/cli_errors.h"

#include <cmath>
#include <exception>
#include <iostream>
#include <stdexcept>

#include "physics/value_text.h"

namespace baize::tools {

void rejectFlag(const std::string& flag, double value, const std::string& allowed) {
  throw UsageError(flag + " = " + physics::valueText(value) + " is not allowed: " + allowed);
}

void requireFiniteFlag(const std::string& flag, double value) {
  if (!std::isfinite(value)) rejectFlag(flag, value, "it must be a finite number");
}

int runReportingErrors(const std::string& command, const std::function<void()>& body) {
  const auto report = [&](const std::exception& error, int status) {
    std::cerr << "baize " << command << ": error: " << error.what() << '\n';
    return status;
  };
  try {
    body();
    // What a command prints is its result: output that could not be written (a full disk, a
    // closed pipe) is a failure, not a success.
    std::cout.flush();
    if (!std::cout) throw std::runtime_error("standard output could not be written");
    return 0;
  } catch (const UsageError& error) {
    return report(error, kExitUsage);
  } catch (const std::invalid_argument& error) {
    return report(error, kExitUsage);
  } catch (const std::exception& error) {
    return report(error, kExitFailure);
  }
}

CLI::Validator notNegative() {
  return CLI::Validator(
      [](std::string& text) {
        return text.find_first_not_of(" \t") != std::string::npos &&
                       text[text.find_first_not_of(" \t")] == '-'
                   ? text + " is not allowed: it must be a whole number >= 0"
                   : std::string();
      },
      "NOT NEGATIVE");
}

CLI::Validator notEmpty() {
  return CLI::Validator(
      [](std::string& text) {
        return text.empty() ? std::string("an empty value is not allowed") : std::string();
      },
      "");
}

}  // namespace baize::tools
