#include "engine/io/ball_set.h"

#include <gtest/gtest.h>

#include <fstream>
#include <limits>
#include <set>
#include <string>

#include "engine/io/table.h"
#include "tests/engine/error_test_support.h"

namespace baize::engine {
namespace {

TEST(BuiltinBallSets, EveryShippedSetLoads) {
  for (const std::string& name : builtinBallSetNames()) {
    const BallSet set = builtinBallSet(name);
    EXPECT_EQ(set.name, name);
    EXPECT_TRUE(set.contains("cue"));
  }
}

TEST(BuiltinBallSets, PoolSetIsTheCueBallAndOneToFifteenWithStripesNineToFifteen) {
  const BallSet set = builtinBallSet("pool");
  EXPECT_DOUBLE_EQ(set.radius_m, 0.028575);
  EXPECT_DOUBLE_EQ(set.mass_kg, 0.17);
  ASSERT_EQ(set.balls.size(), 16u);
  EXPECT_EQ(set.ball("cue").number, 0);
  EXPECT_FALSE(set.ball("cue").stripe);
  for (int number = 1; number <= 15; ++number) {
    const BallSpec& ball = set.ball(std::to_string(number));
    EXPECT_EQ(ball.number, number);
    EXPECT_EQ(ball.stripe, number >= 9);
    // A stripe wears the colour of the solid eight below it.
    if (number >= 9) {
      EXPECT_EQ(ball.colour, set.ball(std::to_string(number - 8)).colour);
    }
  }
  EXPECT_EQ(set.ball("8").colour, "#000000");
}

TEST(BuiltinBallSets, SnookerSetIsTheCueBallFifteenRedsAndSixColours) {
  const BallSet set = builtinBallSet("snooker");
  EXPECT_DOUBLE_EQ(set.radius_m, 0.02625);
  EXPECT_DOUBLE_EQ(set.mass_kg, 0.1406);
  ASSERT_EQ(set.balls.size(), 22u);
  std::set<std::string> red_colours;
  for (int red = 1; red <= 15; ++red)
    red_colours.insert(set.ball("red" + std::to_string(red)).colour);
  EXPECT_EQ(red_colours.size(), 1u);
  std::set<std::string> colours(red_colours);
  for (const std::string id : {"cue", "yellow", "green", "brown", "blue", "pink", "black"}) {
    colours.insert(set.ball(id).colour);
  }
  EXPECT_EQ(colours.size(), 8u);  // every kind of ball looks different
}

TEST(BuiltinBallSets, UnknownIdOrNameIsNamed) {
  EXPECT_MENTIONS(invalidArgumentMessage([] { builtinBallSet("pool").ball("16"); }), "\"16\"");
  EXPECT_MENTIONS(invalidArgumentMessage([] { builtinBallSet("carom"); }), "\"carom\"");
}

class BadBallSetFileTest : public ::testing::Test {
 protected:
  nlohmann::json document =
      nlohmann::json::parse(std::ifstream(assetsDirectory() + "/balls/pool.json"));
  // One file per test: ctest runs tests in parallel processes.
  std::string path = ::testing::TempDir() + "bad_balls_" +
                     ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".json";

  std::string loadError() {
    std::ofstream(path) << document.dump(2);
    return invalidArgumentMessage([&] { loadBallSet(path); });
  }
};

TEST_F(BadBallSetFileTest, UnknownKeyInABallIsNamedWithItsIndex) {
  document["balls"][2]["weight_kg"] = 0.2;
  const std::string message = loadError();
  EXPECT_MENTIONS(message, path);
  EXPECT_MENTIONS(message, "balls[2].weight_kg = 0.2");
  EXPECT_MENTIONS(message, "unknown key");
}

TEST_F(BadBallSetFileTest, MissingKeyIsNamed) {
  document.erase("mass_kg");
  EXPECT_MENTIONS(loadError(), "mass_kg is missing");
}

TEST_F(BadBallSetFileTest, NegativeRadiusIsNamed) {
  document["radius_m"] = -0.028575;
  EXPECT_MENTIONS(loadError(), "radius_m = -0.028575");
}

TEST_F(BadBallSetFileTest, NonFiniteMassIsNamed) {
  document["mass_kg"] = std::numeric_limits<double>::infinity();
  EXPECT_MENTIONS(invalidArgumentMessage([&] { ballSetFromJson(document, "set"); }),
                  "set: mass_kg = inf");
}

TEST_F(BadBallSetFileTest, WrongTypesAreNamed) {
  document["balls"][1]["stripe"] = "no";
  EXPECT_MENTIONS(loadError(), "balls[1].stripe = \"no\"");
  document["balls"][1]["stripe"] = false;
  document["balls"][3]["number"] = 3.5;
  EXPECT_MENTIONS(loadError(), "balls[3].number = 3.5");
}

TEST_F(BadBallSetFileTest, DuplicateIdBadColourAndMissingCueAreRejected) {
  document["balls"][4]["id"] = "3";
  EXPECT_MENTIONS(loadError(), "balls[4].id = \"3\"");
  document["balls"][4]["id"] = "4";
  document["balls"][5]["colour"] = "orange";
  EXPECT_MENTIONS(loadError(), "balls[5].colour = \"orange\"");
  document["balls"][5]["colour"] = "#ff7f00";
  document["balls"][0]["id"] = "white";
  EXPECT_MENTIONS(loadError(), "\"cue\"");
}

}  // namespace
}  // namespace baize::engine
