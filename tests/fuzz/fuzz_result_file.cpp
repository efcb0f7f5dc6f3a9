// Fuzz target: engine::resultFromJson on arbitrary bytes. Bytes that are not JSON are refused by
// the JSON parser (its exceptions are fine); a document is either refused with
// std::invalid_argument or read, and a result read must be written and read again to the same
// document (one writer, one reader, bit for bit). Any other exception, a crash or a hang is a
// finding.
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "engine/io/result_file.h"
#include "tests/fuzz/fuzz_json.h"
#include "tests/fuzz/fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace baize;
  nlohmann::json document;
  if (!baize::fuzz::parseJson(data, size, &document)) return 0;
  engine::ShotResult result;
  try {
    // A folder that does not exist: an embedded scene naming a file is refused before it is opened.
    result = engine::resultFromJson(document, "fuzz-no-such-folder/result.json");
  } catch (const std::invalid_argument&) {
    return 0;
  }
  const nlohmann::json written = engine::resultJson(result);
  try {
    const engine::ShotResult again = engine::resultFromJson(written, "written.json");
    fuzz::check(engine::resultJson(again) == written, "a result read back writes another document");
  } catch (const std::invalid_argument& e) {
    fuzz::fail(std::string("a result read and written again is refused: ") + e.what());
  }
  return 0;
}
