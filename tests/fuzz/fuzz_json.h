// The parser targets' first step: the fuzzer's bytes as a JSON document, or nothing to test (a file
// that is not JSON is turned into std::invalid_argument by the loaders, before any parser runs).
#pragma once

#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>

namespace baize::fuzz {

inline bool parseJson(const std::uint8_t* data, std::size_t size, nlohmann::json* document) {
  try {
    *document = nlohmann::json::parse(data, data + size);
    return true;
  } catch (const nlohmann::json::exception&) {
    return false;
  }
}

}  // namespace baize::fuzz
