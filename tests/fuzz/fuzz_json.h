// The parser targets' first step: the fuzzer's bytes as a JSON document, or nothing to test (a file
// that is not JSON, or has a key twice in an object, is turned into std::invalid_argument by the
// loaders, before any parser runs).
#pragma once

#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>

#include "engine/io/json_reader.h"

namespace baize::fuzz {

inline bool parseJson(const std::uint8_t* data, std::size_t size, nlohmann::json* document) {
  try {
    // The loaders' own parse, so that the duplicate-key check is fuzzed too.
    *document = engine::JsonReader::parseText(
        std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

}  // namespace baize::fuzz
