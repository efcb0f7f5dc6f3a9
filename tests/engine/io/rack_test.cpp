#include "engine/io/rack.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <ostream>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "physics/value_text.h"
#include "tests/engine/error_test_support.h"

namespace baize::engine {
namespace {

using Eigen::Vector2d;

// Rack coordinates are a few sums of metre-sized numbers: rounding stays far below this.
constexpr double kRoundingDistance_m = 1e-12;

struct RackCase {
  std::string rack;
  std::string table;
  std::string balls;
  std::size_t count;         // balls placed, cue ball included
  std::size_t frozen_pairs;  // neighbour pairs at 2R + gap
  std::size_t jittered;      // balls of the triangle or diamond
};

void PrintTo(const RackCase& c, std::ostream* out) { *out << c.rack << " on " << c.table; }

// A triangle of n rows has 3 n (n - 1) / 2 touching pairs; the 1-2-3-2-1 diamond has 16; the
// snooker rack adds the pink against the apex red.
const std::vector<RackCase> kRackCases = {
    {"8-ball", "pool-7ft", "pool", 16, 30, 15},  {"8-ball", "pool-8ft", "pool", 16, 30, 15},
    {"8-ball", "pool-9ft", "pool", 16, 30, 15},  {"9-ball", "pool-9ft", "pool", 10, 16, 9},
    {"9-ball", "pool-7ft", "pool", 10, 16, 9},   {"10-ball", "pool-9ft", "pool", 11, 18, 10},
    {"10-ball", "pool-7ft", "pool", 11, 18, 10}, {"snooker", "snooker-12ft", "snooker", 22, 31, 15},
};

std::map<std::string, Vector2d> byId(const std::vector<PlacedBall>& placed) {
  std::map<std::string, Vector2d> positions;
  for (const PlacedBall& ball : placed) positions[ball.id] = ball.position_m;
  return positions;
}

std::size_t pairsAtDistance(const std::vector<PlacedBall>& placed, double distance_m) {
  std::size_t pairs = 0;
  for (std::size_t i = 0; i < placed.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      const double d = (placed[i].position_m - placed[j].position_m).norm();
      if (std::abs(d - distance_m) <= kRoundingDistance_m) ++pairs;
    }
  }
  return pairs;
}

double closestPair(const std::vector<PlacedBall>& placed) {
  double closest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < placed.size(); ++i) {
    for (std::size_t j = 0; j < i; ++j) {
      closest = std::min(closest, (placed[i].position_m - placed[j].position_m).norm());
    }
  }
  return closest;
}

class RackTest : public ::testing::TestWithParam<RackCase> {
 protected:
  Table table = builtinTable(GetParam().table);
  BallSet balls = builtinBallSet(GetParam().balls);
  double radius = balls.radius_m;
};

TEST_P(RackTest, PlacesTheRightBallsOnceEach) {
  const auto placed = placeRack(GetParam().rack, table, balls);
  EXPECT_EQ(placed.size(), GetParam().count);
  EXPECT_EQ(byId(placed).size(), placed.size());
  EXPECT_EQ(placed.front().id, "cue");
  for (const PlacedBall& ball : placed) EXPECT_TRUE(balls.contains(ball.id)) << ball.id;
}

TEST_P(RackTest, NoOverlapAndAllOnThePlayingSurface) {
  const auto placed = placeRack(GetParam().rack, table, balls);
  EXPECT_GE(closestPair(placed), 2 * radius);
  for (const PlacedBall& ball : placed) {
    EXPECT_LE(std::abs(ball.position_m.x()), table.length_m / 2 - radius) << ball.id;
    EXPECT_LE(std::abs(ball.position_m.y()), table.width_m / 2 - radius) << ball.id;
  }
}

TEST_P(RackTest, FrozenNeighboursAreTwoRadiiPlusTheGapApart) {
  for (const double gap_m : {kFrozenGap_m, 1e-4}) {
    RackOptions options;
    options.gap_m = gap_m;
    const auto placed = placeRack(GetParam().rack, table, balls, options);
    EXPECT_EQ(pairsAtDistance(placed, 2 * radius + gap_m), GetParam().frozen_pairs) << gap_m;
    EXPECT_NEAR(closestPair(placed), 2 * radius + gap_m, kRoundingDistance_m);
  }
}

TEST_P(RackTest, SameSeedSamePositionsOtherSeedOtherPositions) {
  RackOptions options;
  options.jitter_radius_m = options.gap_m / 2;
  options.jitter_seed = 42;
  const auto first = placeRack(GetParam().rack, table, balls, options);
  const auto again = placeRack(GetParam().rack, table, balls, options);
  options.jitter_seed = 43;
  const auto other = placeRack(GetParam().rack, table, balls, options);
  ASSERT_EQ(first.size(), again.size());
  ASSERT_EQ(first.size(), other.size());
  std::size_t moved_by_seed = 0;
  for (std::size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ(first[i].id, again[i].id);
    EXPECT_EQ(first[i].position_m, again[i].position_m);  // bit for bit
    if (first[i].position_m != other[i].position_m) ++moved_by_seed;
  }
  EXPECT_EQ(moved_by_seed, GetParam().jittered);
}

TEST_P(RackTest, JitterStaysWithinItsRadiusAndNeverOverlaps) {
  RackOptions options;
  options.gap_m = 1e-4;  // a visible jitter, as large as allowed
  const auto unjittered = byId(placeRack(GetParam().rack, table, balls, options));
  options.jitter_radius_m = options.gap_m / 2;
  for (std::uint64_t seed = 0; seed < 50; ++seed) {
    options.jitter_seed = seed;
    const auto placed = placeRack(GetParam().rack, table, balls, options);
    EXPECT_GE(closestPair(placed), 2 * radius);
    for (const PlacedBall& ball : placed) {
      EXPECT_LE((ball.position_m - unjittered.at(ball.id)).norm(), options.jitter_radius_m);
    }
  }
}

// The gap jitteredRackGap_m gives is the tightest that never overlaps: the frozen gap for a jitter
// within half of it, twice the jitter beyond, up to the largest jitter (whose gap is the largest
// accepted); every rack jittered by the largest radius at that gap stays apart.
TEST_P(RackTest, JitteredRackGapIsTheTightestThatNeverOverlaps) {
  EXPECT_EQ(jitteredRackGap_m(0), kFrozenGap_m);
  EXPECT_EQ(jitteredRackGap_m(kFrozenGap_m / 2), kFrozenGap_m);
  EXPECT_EQ(jitteredRackGap_m(2e-5), 4e-5);
  EXPECT_EQ(jitteredRackGap_m(kMaxJitterRadius_m), kMaxGap_m);
  RackOptions options;
  options.jitter_radius_m = kMaxJitterRadius_m;
  options.gap_m = jitteredRackGap_m(options.jitter_radius_m);
  for (std::uint64_t seed = 0; seed < 20; ++seed) {
    options.jitter_seed = seed;
    EXPECT_GE(closestPair(placeRack(GetParam().rack, table, balls, options)), 2 * radius);
  }
}

INSTANTIATE_TEST_SUITE_P(Racks, RackTest, ::testing::ValuesIn(kRackCases), [](const auto& info) {
  std::string name = info.param.rack + "_on_" + info.param.table;
  for (char& c : name) {
    if (c == '-') c = '_';
  }
  return name;
});

// Pool: row r of the rack lies r row steps behind the foot spot.
double rowX(const Table& table, const BallSet& balls, int row) {
  return table.pool_markings->foot_spot_m.x() +
         row * (2 * balls.radius_m + kFrozenGap_m) * std::sqrt(3.0) / 2;
}

TEST(PoolRacks, ApexBallOnTheFootSpotAndCueBallOnTheHeadSpot) {
  const Table table = builtinTable("pool-9ft");
  const BallSet balls = builtinBallSet("pool");
  for (const std::string rack : {"8-ball", "9-ball", "10-ball"}) {
    const auto positions = byId(placeRack(rack, table, balls));
    EXPECT_EQ(positions.at("1"), table.pool_markings->foot_spot_m) << rack;
    EXPECT_EQ(positions.at("cue"), Vector2d(table.pool_markings->head_string_x_m, 0)) << rack;
  }
}

TEST(PoolRacks, EightBallHasTheEightInTheCentreAndASolidAndAStripeInTheBackCorners) {
  const Table table = builtinTable("pool-8ft");
  const BallSet balls = builtinBallSet("pool");
  const auto placed = placeRack("8-ball", table, balls);
  const auto positions = byId(placed);
  EXPECT_NEAR(positions.at("8").x(), rowX(table, balls, 2), kRoundingDistance_m);
  EXPECT_EQ(positions.at("8").y(), 0);
  std::vector<const BallSpec*> corners;
  for (const PlacedBall& ball : placed) {
    const bool back_row =
        std::abs(ball.position_m.x() - rowX(table, balls, 4)) <= kRoundingDistance_m;
    const bool outermost = std::abs(std::abs(ball.position_m.y()) -
                                    2 * (2 * balls.radius_m + kFrozenGap_m)) <= kRoundingDistance_m;
    if (back_row && outermost) corners.push_back(&balls.ball(ball.id));
  }
  ASSERT_EQ(corners.size(), 2u);
  EXPECT_NE(corners[0]->stripe, corners[1]->stripe);
  EXPECT_NE(corners[0]->number, 8);
  EXPECT_NE(corners[1]->number, 8);
}

TEST(PoolRacks, NineBallDiamondHasTheNineAtItsCentre) {
  const Table table = builtinTable("pool-9ft");
  const auto placed = placeRack("9-ball", table, builtinBallSet("pool"));
  Vector2d centroid = Vector2d::Zero();
  for (std::size_t i = 1; i < placed.size(); ++i) centroid += placed[i].position_m;
  centroid /= static_cast<double>(placed.size() - 1);
  EXPECT_NEAR((byId(placed).at("9") - centroid).norm(), 0, kRoundingDistance_m);
}

TEST(PoolRacks, TenBallHasTheTenInTheMiddleOfTheThirdRow) {
  const Table table = builtinTable("pool-9ft");
  const BallSet balls = builtinBallSet("pool");
  const auto positions = byId(placeRack("10-ball", table, balls));
  EXPECT_NEAR(positions.at("10").x(), rowX(table, balls, 2), kRoundingDistance_m);
  EXPECT_EQ(positions.at("10").y(), 0);
}

TEST(SnookerRack, ColoursOnTheirSpotsRedsBehindThePinkCueBallInTheD) {
  const Table table = builtinTable("snooker-12ft");
  const BallSet balls = builtinBallSet("snooker");
  const SnookerMarkings& spots = *table.snooker_markings;
  const auto positions = byId(placeRack("snooker", table, balls));
  EXPECT_EQ(positions.at("yellow"), spots.yellow_spot_m);
  EXPECT_EQ(positions.at("green"), spots.green_spot_m);
  EXPECT_EQ(positions.at("brown"), spots.brown_spot_m);
  EXPECT_EQ(positions.at("blue"), spots.blue_spot_m);
  EXPECT_EQ(positions.at("pink"), spots.pink_spot_m);
  EXPECT_EQ(positions.at("black"), spots.black_spot_m);
  EXPECT_NEAR((positions.at("red1") - spots.pink_spot_m).norm(), 2 * balls.radius_m + kFrozenGap_m,
              kRoundingDistance_m);
  for (int red = 1; red <= 15; ++red) {
    const Vector2d& p = positions.at("red" + std::to_string(red));
    EXPECT_GT(p.x(), spots.pink_spot_m.x());
    EXPECT_LT(p.x(), spots.black_spot_m.x() - 2 * balls.radius_m);
  }
  const Vector2d& cue = positions.at("cue");
  EXPECT_LE(cue.x(), spots.baulk_line_x_m);
  EXPECT_LE((cue - spots.brown_spot_m).norm(), spots.d_radius_m);
}

TEST(RackErrors, BadNamesTablesBallSetsAndOptionsAreNamed) {
  const Table pool = builtinTable("pool-9ft");
  const Table snooker = builtinTable("snooker-12ft");
  const BallSet pool_balls = builtinBallSet("pool");
  EXPECT_MENTIONS(invalidArgumentMessage([&] { placeRack("7-ball", pool, pool_balls); }),
                  "\"7-ball\"");
  EXPECT_MENTIONS(invalidArgumentMessage([&] { placeRack("8-ball", snooker, pool_balls); }),
                  "needs a pool table");
  EXPECT_MENTIONS(invalidArgumentMessage([&] { placeRack("snooker", snooker, pool_balls); }),
                  "\"red1\"");
  RackOptions options;
  options.gap_m = 0;
  EXPECT_MENTIONS(invalidArgumentMessage([&] { placeRack("8-ball", pool, pool_balls, options); }),
                  "gap_m = 0");
  options.gap_m = std::numeric_limits<double>::quiet_NaN();
  EXPECT_MENTIONS(invalidArgumentMessage([&] { placeRack("8-ball", pool, pool_balls, options); }),
                  "gap_m = nan");
  options.gap_m = 1e-6;
  options.jitter_radius_m = 6e-7;
  EXPECT_MENTIONS(invalidArgumentMessage([&] { placeRack("8-ball", pool, pool_balls, options); }),
                  "jitter_radius_m = " + physics::valueText(6e-7));
}

TEST(RackErrors, ARackThatDoesNotFitTheTableIsRejected) {
  nlohmann::json document =
      nlohmann::json::parse(std::ifstream(assetsDirectory() + "/tables/pool-7ft.json"));
  document["playing_surface"]["length_m"] = 0.6;
  document["playing_surface"]["width_m"] = 0.3;
  const Table tiny = tableFromJson(document, "tiny");
  EXPECT_MENTIONS(
      invalidArgumentMessage([&] { placeRack("8-ball", tiny, builtinBallSet("pool")); }),
      "does not fit");
}

}  // namespace
}  // namespace baize::engine
