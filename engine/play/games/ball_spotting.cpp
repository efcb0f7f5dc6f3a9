#include "engine/play/games/ball_spotting.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace baize::engine {
namespace {

using Eigen::Vector2d;

// How far along the line the nearest free point lies: the start, or the far end of the span a
// ball blocks, whichever is the first point no ball blocks. Spans are solved exactly from
// |start + s d - b| = 2R + gap.
std::optional<double> firstFreeDistance(const std::vector<PlacedBall>& balls, const Vector2d& start,
                                        const Vector2d& direction, const Table& table,
                                        double radius_m) {
  std::vector<double> candidates{0};
  const double reach = 2 * radius_m + kSpotGap_m;
  for (const PlacedBall& b : balls) {
    const Vector2d offset = start - b.position_m;
    const double along = offset.dot(direction);
    const double disc = along * along - (offset.squaredNorm() - reach * reach);
    if (disc >= 0) candidates.push_back(-along + std::sqrt(disc));
  }
  std::sort(candidates.begin(), candidates.end());
  for (double s : candidates) {
    if (s >= 0 && spotFree(balls, start + s * direction, table, radius_m)) return s;
  }
  return std::nullopt;
}

}  // namespace

bool spotFree(const std::vector<PlacedBall>& balls, const Vector2d& point_m, const Table& table,
              double radius_m) {
  if (!(std::abs(point_m.x()) <= table.length_m / 2 - radius_m &&
        std::abs(point_m.y()) <= table.width_m / 2 - radius_m)) {
    return false;
  }
  // Rounding of the exact spans may leave a point a hair inside: allow it, it is far below the gap.
  constexpr double kRoundingSlack_m = 1e-12;
  const double reach = 2 * radius_m + kSpotGap_m - kRoundingSlack_m;
  return std::none_of(balls.begin(), balls.end(), [&](const PlacedBall& b) {
    return (b.position_m - point_m).norm() < reach;
  });
}

std::optional<Vector2d> nearestFreeOnLine(const std::vector<PlacedBall>& balls,
                                          const Vector2d& start_m, const Vector2d& direction,
                                          const Table& table, double radius_m) {
  const std::optional<double> s = firstFreeDistance(balls, start_m, direction, table, radius_m);
  if (!s) return std::nullopt;
  return Vector2d(start_m + *s * direction);
}

void spotPoolBall(const std::string& id, std::vector<PlacedBall>* balls, const Table& table,
                  double radius_m) {
  const Vector2d foot = table.pool_markings.value().foot_spot_m;
  for (const Vector2d& direction : {Vector2d(1, 0), Vector2d(-1, 0)}) {
    if (auto point = nearestFreeOnLine(*balls, foot, direction, table, radius_m)) {
      balls->push_back({id, *point});
      return;
    }
  }
  throw std::logic_error("ball " + id + " cannot be spotted: the long string is full");
}

int snookerValue(const std::string& id) {
  if (isRed(id)) return 1;
  const std::vector<std::string>& colours = snookerColours();
  const auto at = std::find(colours.begin(), colours.end(), id);
  return at == colours.end() ? 0 : static_cast<int>(at - colours.begin()) + 2;
}

bool isRed(const std::string& id) { return id.rfind("red", 0) == 0; }

const std::vector<std::string>& snookerColours() {
  static const std::vector<std::string> colours{"yellow", "green", "brown",
                                                "blue",   "pink",  "black"};
  return colours;
}

Vector2d colourSpot(const std::string& colour, const Table& table) {
  const SnookerMarkings& m = table.snooker_markings.value();
  const Vector2d spots[] = {m.yellow_spot_m, m.green_spot_m, m.brown_spot_m,
                            m.blue_spot_m,   m.pink_spot_m,  m.black_spot_m};
  const int value = snookerValue(colour);
  if (value < 2) throw std::invalid_argument("'" + colour + "' is not a snooker colour");
  return spots[value - 2];
}

std::vector<std::string> spotSnookerColours(std::vector<std::string> colours,
                                            std::vector<PlacedBall>* balls, const Table& table,
                                            double radius_m) {
  std::sort(colours.begin(), colours.end(), [](const std::string& a, const std::string& b) {
    return snookerValue(a) > snookerValue(b);
  });
  std::vector<std::string> placed, waiting;
  for (const std::string& c : colours) {  // own spots first: no other colour may take them
    if (spotFree(*balls, colourSpot(c, table), table, radius_m)) {
      balls->push_back({c, colourSpot(c, table)});
      placed.push_back(c);
    } else {
      waiting.push_back(c);
    }
  }
  const std::vector<std::string>& all = snookerColours();
  for (const std::string& c : waiting) {
    std::optional<Vector2d> point;
    for (auto spot = all.rbegin(); spot != all.rend() && !point; ++spot) {
      if (spotFree(*balls, colourSpot(*spot, table), table, radius_m)) {
        point = colourSpot(*spot, table);
      }
    }
    for (const Vector2d& direction : {Vector2d(1, 0), Vector2d(-1, 0)}) {
      if (!point) point = nearestFreeOnLine(*balls, colourSpot(c, table), direction, table, radius_m);
    }
    if (!point) throw std::logic_error("colour " + c + " cannot be spotted: the table is full");
    balls->push_back({c, *point});
    placed.push_back(c);
  }
  return placed;
}

}  // namespace baize::engine
