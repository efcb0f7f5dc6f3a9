// Fuzz target: engine::tableFromJson on arbitrary bytes. Bytes that are not JSON are refused by the
// JSON parser (its exceptions are fine); a document is either refused with std::invalid_argument
// or gives a table whose geometry is finite. Any other exception, a crash or a hang is a finding.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "engine/io/table.h"
#include "engine/sim/shot_simulator.h"
#include "tests/fuzz/fuzz_json.h"
#include "tests/fuzz/fuzz_support.h"

namespace {

// How far a cushion's inward normal may be from unit length: it is a normalised difference of two
// points, a few ulps off at most.
constexpr double kUnitTolerance = 1e-12;
// The shipped pool balls' radius, m: the capture check is exercised for it.
constexpr double kPoolBallRadius_m = 0.028575;

void checkFinite(const Eigen::Vector2d& p, const char* what) {
  baize::fuzz::check(std::isfinite(p.x()) && std::isfinite(p.y()),
                     std::string("a loaded table has a non-finite ") + what);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  nlohmann::json document;
  if (!baize::fuzz::parseJson(data, size, &document)) return 0;
  baize::engine::Table table;
  try {
    table = baize::engine::tableFromJson(document, "fuzz-table.json");
  } catch (const std::invalid_argument&) {
    return 0;
  }
  const baize::engine::TableGeometry geometry = baize::engine::geometryOf(table);
  baize::fuzz::check(!geometry.cushions.empty(), "a loaded table has no cushions");
  for (const auto& c : geometry.cushions) {
    baize::fuzz::check(std::abs(c.inward_normal.norm() - 1) < kUnitTolerance,
                       "a cushion normal is not a unit vector");
    checkFinite(c.start_m, "cushion start");
    checkFinite(c.end_m, "cushion end");
    checkFinite(c.inward_normal, "cushion normal");
  }
  for (const auto& j : geometry.jaws) checkFinite(j.centre_m, "jaw centre");
  for (const auto& p : geometry.pockets) checkFinite(p.centre_m, "pocket centre");
  baize::fuzz::check(geometry.outline.size() == 2 * geometry.cushions.size(),
                     "the cushion outline is not the cushions' ends");
  // Where a scene meets the table: for a pool ball the capture circles cover the openings or the
  // table is refused with std::invalid_argument (anything else escapes as a finding).
  try {
    baize::engine::checkCapturesCoverOpenings(table, kPoolBallRadius_m);
  } catch (const std::invalid_argument&) {
  }
  return 0;
}
