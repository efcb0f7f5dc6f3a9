// Checking that physics refuses bad input: the call throws std::invalid_argument and its message
// names what was refused. One copy for every physics test.
#pragma once

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace baize::physics::test {

// Runs `call`, which must throw std::invalid_argument whose message holds every one of `parts`.
inline void expectRejected(const std::function<void()>& call,
                           const std::vector<std::string>& parts) {
  try {
    call();
    ADD_FAILURE() << "no exception; expected one naming " << ::testing::PrintToString(parts);
  } catch (const std::invalid_argument& error) {
    for (const std::string& part : parts) EXPECT_THAT(error.what(), ::testing::HasSubstr(part));
  }
}

// (A const char* rather than a std::string, so that a braced list of parts never reads as one.)
inline void expectRejected(const std::function<void()>& call, const char* part) {
  expectRejected(call, std::vector<std::string>{part});
}

// As above, for a value refused by rejectValue: the message also says "is not allowed".
inline void expectValueRejected(const std::function<void()>& call, const std::string& part) {
  expectRejected(call, std::vector<std::string>{part, "is not allowed"});
}

}  // namespace baize::physics::test
