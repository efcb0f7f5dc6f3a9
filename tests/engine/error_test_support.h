// Checking std::invalid_argument messages in engine tests.
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <stdexcept>
#include <string>

namespace baize::engine {

// The message of the std::invalid_argument that `action` throws; a test failure if it throws none.
inline std::string invalidArgumentMessage(const std::function<void()>& action) {
  try {
    action();
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  ADD_FAILURE() << "no std::invalid_argument";
  return "";
}

}  // namespace baize::engine

#define EXPECT_MENTIONS(message, part) \
  EXPECT_NE((message).find(part), std::string::npos) << "\"" << (message) << "\" lacks " << (part)
