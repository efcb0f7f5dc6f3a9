#include "engine/fit/cushion_measurements.h"

#include <cmath>
#include <set>
#include <stdexcept>

#include "engine/io/csv_table.h"
#include "physics/value_text.h"

namespace baize::engine {
namespace {

// Rounding allowance of the energy bound: a measured rebound is refused only when it needs more
// than this share above the incoming kinetic energy (speeds are typed with a few digits).
constexpr double kEnergyRoundingShare = 1e-9;

struct Columns {
  size_t speed, angle, rebound_speed;
  std::optional<size_t> topspin, sidespin, rebound_angle;
};

std::optional<size_t> optionalColumn(const CsvTable& table, const std::string& name) {
  if (!table.hasColumn(name)) return std::nullopt;
  return table.column(name);
}

[[noreturn]] void refuse(const CsvTable& table, size_t row, const std::string& column, double value,
                         const std::string& allowed) {
  throw std::invalid_argument(table.path() + " line " + std::to_string(table.lineNumber(row)) +
                              ", column " + column + " = " + physics::valueText(value) +
                              " is not allowed: " + allowed);
}

CushionMeasurement rowOf(const CsvTable& table, const Columns& c, size_t row) {
  CushionMeasurement m;
  m.line = table.lineNumber(row);
  m.speed_mps = table.number(row, c.speed);
  if (!(m.speed_mps > 0)) refuse(table, row, "speed_mps", m.speed_mps, "it must be > 0 (m/s)");
  m.angle_deg = table.number(row, c.angle);
  if (!(m.angle_deg > 0 && m.angle_deg < 180)) {
    refuse(table, row, "angle_deg", m.angle_deg,
           "it must lie strictly between 0 and 180 degrees (90 is head-on)");
  }
  if (c.topspin) m.topspin_k = table.number(row, *c.topspin);
  if (c.sidespin) m.sidespin_k = table.number(row, *c.sidespin);
  m.rebound_speed_mps = table.number(row, c.rebound_speed);
  if (!(m.rebound_speed_mps > 0)) {
    refuse(table, row, "rebound_speed_mps", m.rebound_speed_mps,
           "it must be > 0 (m/s): the model always sends the ball back");
  }
  // Kinetic energy per unit mass in: V0^2 / 2 (1 + 2/5 (kT^2 + kS^2)) for a solid ball; the
  // rebound's translation cannot take more.
  const double most_mps =
      m.speed_mps * std::sqrt(1 + 0.4 * (m.topspin_k * m.topspin_k + m.sidespin_k * m.sidespin_k));
  if (m.rebound_speed_mps > most_mps * (1 + kEnergyRoundingShare)) {
    refuse(table, row, "rebound_speed_mps", m.rebound_speed_mps,
           "it must be at most " + physics::valueText(most_mps) +
               " m/s, all the energy the incoming ball carries with its spin");
  }
  if (c.rebound_angle && !table.text(row, *c.rebound_angle).empty()) {
    m.rebound_angle_deg = table.number(row, *c.rebound_angle);
    if (!(*m.rebound_angle_deg > 0 && *m.rebound_angle_deg < 180)) {
      refuse(table, row, "rebound_angle_deg", *m.rebound_angle_deg,
             "it must lie strictly between 0 and 180 degrees: the ball leaves the cushion");
    }
  }
  return m;
}

}  // namespace

std::vector<CushionMeasurement> readCushionMeasurements(const std::string& path) {
  const CsvTable table = CsvTable::read(path);
  // A misspelt optional column would silently read as its default (a rolling ball): refused.
  static const std::set<std::string> known = {"speed_mps",        "angle_deg",
                                              "topspin",          "sidespin",
                                              "rebound_speed_mps", "rebound_angle_deg"};
  for (const std::string& name : table.header()) {
    if (!known.count(name)) {
      throw std::invalid_argument(path + " line 1: column '" + name +
                                  "' is not allowed: the columns are speed_mps, angle_deg, "
                                  "topspin, sidespin, rebound_speed_mps, rebound_angle_deg");
    }
  }
  const Columns columns{table.column("speed_mps"),       table.column("angle_deg"),
                        table.column("rebound_speed_mps"), optionalColumn(table, "topspin"),
                        optionalColumn(table, "sidespin"), optionalColumn(table, "rebound_angle_deg")};
  std::vector<CushionMeasurement> measurements;
  for (size_t row = 0; row < table.rowCount(); ++row) {
    measurements.push_back(rowOf(table, columns, row));
  }
  if (measurements.empty()) {
    throw std::invalid_argument(path + ": no measurements: the file must have rows below its header");
  }
  return measurements;
}

}  // namespace baize::engine
