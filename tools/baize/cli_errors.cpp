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

std::string namingTheFlag(const std::string& model_message, const std::string& quantity,
                          const std::string& flag) {
  if (model_message.rfind(quantity, 0) != 0) return model_message;
  return flag + model_message.substr(quantity.size()) + " (" + quantity + ")";
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

CLI::Validator unsigned64() {
  return CLI::Validator(
      [](std::string& text) {
        // An optional '+', then digits, at most 2^64 - 1 (CLI11 would wrap "-1" and accept more).
        std::string digits = text;
        digits.erase(0, digits.find_first_not_of(" \t"));
        if (!digits.empty() && digits[0] == '+') digits.erase(0, 1);
        const std::string largest = "18446744073709551615";
        const bool whole = !digits.empty() &&
                           digits.find_first_not_of("0123456789") == std::string::npos;
        if (whole) digits.erase(0, std::min(digits.find_first_not_of('0'), digits.size() - 1));
        const bool fits = whole && (digits.size() < largest.size() ||
                                    (digits.size() == largest.size() && digits <= largest));
        return fits ? std::string()
                    : text + " is not allowed: it must be a whole number in [0, 2^64 - 1]";
      },
      "");
}

CLI::Validator notEmpty() {
  return CLI::Validator(
      [](std::string& text) {
        return text.empty() ? std::string("an empty value is not allowed") : std::string();
      },
      "");
}

}  // namespace baize::tools
