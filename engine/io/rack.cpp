#include "engine/io/rack.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "physics/value_text.h"

namespace baize::engine {
namespace {

using Eigen::Vector2d;
using Rows = std::vector<std::vector<std::string>>;

// Rows of balls from the apex towards the foot (+x). Row r holds its balls centred on y = 0 with
// `spacing_m` between centres; rows whose counts differ by one nest, so neighbours in adjacent
// rows are also `spacing_m` apart. Triangles (1, 2, 3, ...) and diamonds (1, 2, 3, 2, 1) alike.
std::vector<PlacedBall> placeRows(const Rows& rows, const Vector2d& apex_m, double spacing_m) {
  const double row_step_m = spacing_m * std::sqrt(3.0) / 2;
  std::vector<PlacedBall> placed;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    const double count = static_cast<double>(rows[r].size());
    for (std::size_t j = 0; j < rows[r].size(); ++j) {
      const double y = (static_cast<double>(j) - (count - 1) / 2) * spacing_m;
      placed.push_back({rows[r][j], apex_m + Vector2d(static_cast<double>(r) * row_step_m, y)});
    }
  }
  return placed;
}

// A uniform double in [0, 1) from the top 53 bits: the same on every platform, unlike
// std::uniform_real_distribution whose algorithm the standard leaves open.
double unitUniform(std::mt19937_64& generator) {
  return static_cast<double>(generator() >> 11) * 0x1.0p-53;
}

// Uniform in the disc of the given radius, by rejection from the square (no trigonometry, so the
// result is the same bit for bit everywhere).
Vector2d discUniform(std::mt19937_64& generator, double radius_m) {
  while (true) {
    const Vector2d offset(2 * unitUniform(generator) - 1, 2 * unitUniform(generator) - 1);
    if (offset.squaredNorm() <= 1) return radius_m * offset;
  }
}

void validateOptions(const RackOptions& options) {
  if (!(options.gap_m > 0 && options.gap_m <= kMaxGap_m)) {
    physics::rejectValue("rack gap_m", options.gap_m,
                         "it must lie in (0, " + physics::valueText(kMaxGap_m) + "] m");
  }
  if (!(options.jitter_radius_m >= 0 && options.jitter_radius_m <= options.gap_m / 2)) {
    physics::rejectValue("rack jitter_radius_m", options.jitter_radius_m,
                         "it must lie in [0, gap_m / 2 = " + physics::valueText(options.gap_m / 2) +
                             "] m so that jittered neighbours never overlap");
  }
}

void requireKind(const std::string& rack_name, const Table& table, TableKind kind) {
  if (table.kind != kind) {
    throw std::invalid_argument("rack \"" + rack_name + "\" is not allowed on table \"" +
                                table.name + "\": it needs a " +
                                (kind == TableKind::Pool ? "pool" : "snooker") + " table");
  }
}

// Every ball on the playing surface and no two overlapping; otherwise the rack does not fit.
void checkFits(const std::string& rack_name, const Table& table, const BallSet& balls,
               const std::vector<PlacedBall>& placed) {
  const double radius = balls.radius_m;
  for (std::size_t i = 0; i < placed.size(); ++i) {
    const Vector2d& p = placed[i].position_m;
    if (!(std::abs(p.x()) <= table.length_m / 2 - radius &&
          std::abs(p.y()) <= table.width_m / 2 - radius)) {
      throw std::invalid_argument("rack \"" + rack_name + "\" does not fit on table \"" +
                                  table.name + "\": ball " + placed[i].id +
                                  " would lie off the playing surface");
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (!((p - placed[j].position_m).norm() >= 2 * radius)) {
        throw std::invalid_argument("rack \"" + rack_name + "\" does not fit on table \"" +
                                    table.name + "\": balls " + placed[j].id + " and " +
                                    placed[i].id + " would overlap");
      }
    }
  }
}

}  // namespace

double jitteredRackGap_m(double jitter_radius_m) {
  return std::max(kFrozenGap_m, 2 * jitter_radius_m);
}

std::vector<std::string> rackNames() { return {"8-ball", "9-ball", "10-ball", "snooker"}; }

std::vector<PlacedBall> placeRack(const std::string& rack_name, const Table& table,
                                  const BallSet& balls, const RackOptions& options) {
  validateOptions(options);
  const double spacing_m = 2 * balls.radius_m + options.gap_m;
  std::vector<PlacedBall> placed;   // the cue ball, then the balls that may be jittered
  std::vector<PlacedBall> spotted;  // balls on their spots, never jittered
  if (rack_name == "8-ball" || rack_name == "9-ball" || rack_name == "10-ball") {
    requireKind(rack_name, table, TableKind::Pool);
    const PoolMarkings& markings = *table.pool_markings;
    placed.push_back({"cue", markings.head_spot_m});
    Rows rows;
    if (rack_name == "8-ball") {
      // 8 in the centre; the back corners a solid (6) and a stripe (12).
      rows = {{"1"},
              {"11", "5"},
              {"2", "8", "10"},
              {"9", "7", "14", "4"},
              {"6", "15", "13", "3", "12"}};
    } else if (rack_name == "9-ball") {
      rows = {{"1"}, {"2", "3"}, {"4", "9", "5"}, {"6", "7"}, {"8"}};
    } else {
      rows = {{"1"}, {"2", "3"}, {"4", "10", "5"}, {"6", "7", "8", "9"}};
    }
    for (const PlacedBall& ball : placeRows(rows, markings.foot_spot_m, spacing_m)) {
      placed.push_back(ball);
    }
  } else if (rack_name == "snooker") {
    requireKind(rack_name, table, TableKind::Snooker);
    const SnookerMarkings& markings = *table.snooker_markings;
    placed.push_back({"cue", markings.brown_spot_m - Vector2d(markings.d_radius_m / 2, 0)});
    // The apex red as close behind the pink as the frozen gap allows.
    Rows reds;
    int red = 1;
    for (int row = 1; row <= 5; ++row) {
      reds.emplace_back();
      for (int j = 0; j < row; ++j) reds.back().push_back("red" + std::to_string(red++));
    }
    for (const PlacedBall& ball :
         placeRows(reds, markings.pink_spot_m + Vector2d(spacing_m, 0), spacing_m)) {
      placed.push_back(ball);
    }
    spotted = {{"yellow", markings.yellow_spot_m}, {"green", markings.green_spot_m},
               {"brown", markings.brown_spot_m},   {"blue", markings.blue_spot_m},
               {"pink", markings.pink_spot_m},     {"black", markings.black_spot_m}};
  } else {
    std::string allowed;
    for (const std::string& known : rackNames()) allowed += (allowed.empty() ? "" : ", ") + known;
    throw std::invalid_argument("rack name \"" + rack_name + "\" is not allowed: the racks are " +
                                allowed);
  }

  if (options.jitter_seed) {
    std::mt19937_64 generator(*options.jitter_seed);
    for (std::size_t i = 1; i < placed.size(); ++i) {
      placed[i].position_m += discUniform(generator, options.jitter_radius_m);
    }
  }
  placed.insert(placed.end(), spotted.begin(), spotted.end());
  for (const PlacedBall& ball : placed) balls.ball(ball.id);  // throws for a missing ball
  checkFits(rack_name, table, balls, placed);
  return placed;
}

}  // namespace baize::engine
