// Tests of the Mathavan 2010 parameters the "exact" and "paper" models share: the table's nose
// height by default, the scene keys read over it, and one impact's physics parameters taking the
// ball and cloth from the shot.
#include "engine/models/cushion_mathavan2010.h"

#include <gtest/gtest.h>

#include "tests/engine/error_test_support.h"

namespace baize::engine {
namespace {

TEST(CushionMathavan2010, DefaultsTakeTheTablesNoseHeightAndKeysOverrideThem) {
  ModelDefaults defaults;
  defaults.cushion_contact_height_m = 0.04;
  const Mathavan2010Cushion plain = readMathavan2010(defaults, nullptr);
  EXPECT_EQ(plain.contact_height_m, 0.04);
  EXPECT_EQ(plain.restitution, physics::CushionParams{}.restitution);
  const nlohmann::json group = {
      {"restitution", 0.9}, {"friction", 0.1}, {"contact_height_m", 0.037}};
  const JsonReader reader(group, "t.json");
  const Mathavan2010Cushion read = readMathavan2010(defaults, &reader);
  EXPECT_EQ(read.restitution, 0.9);
  EXPECT_EQ(read.cushion_friction, 0.1);
  EXPECT_EQ(read.contact_height_m, 0.037);
  nlohmann::json echo;
  writeMathavan2010(read, &echo);
  EXPECT_EQ(echo, group);
}

TEST(CushionMathavan2010, AnImpactTakesTheBallAndClothFromTheShot) {
  SimulationParams shot;
  shot.ball.mass_kg = 0.15;
  shot.ball.radius_m = 0.026;
  shot.cloth.sliding_friction = 0.3;
  const physics::CushionParams p = impactParams(Mathavan2010Cushion{0.036, 0.9, 0.1, std::nullopt}, shot);
  EXPECT_EQ(p.mass_kg, 0.15);
  EXPECT_EQ(p.radius_m, 0.026);
  EXPECT_EQ(p.cloth_friction, 0.3);
  EXPECT_EQ(p.contact_height_m, 0.036);
  EXPECT_EQ(p.restitution, 0.9);
  EXPECT_EQ(p.cushion_friction, 0.1);
}

// The speed dependence: none unless given; given, it reaches the impact's parameters and the echo.
TEST(CushionMathavan2010, TheSpeedDependenceIsOffUnlessGiven) {
  const Mathavan2010Cushion plain = readMathavan2010(ModelDefaults{}, nullptr);
  EXPECT_FALSE(plain.restitution_speed_dependence);
  EXPECT_FALSE(impactParams(plain, SimulationParams{}).restitution_speed_dependence);
  nlohmann::json echo;
  writeMathavan2010(plain, &echo);
  EXPECT_FALSE(echo.contains(kRestitutionSpeedDependenceKey));
  const nlohmann::json group = {
      {kRestitutionSpeedDependenceKey, {{"knee_speed_mps", 2.2}, {"falloff_exponent", 0.3}}}};
  const JsonReader reader(group, "t.json", "physics.cushion");
  const Mathavan2010Cushion read = readMathavan2010(ModelDefaults{}, &reader);
  const physics::CushionParams p = impactParams(read, SimulationParams{});
  ASSERT_TRUE(p.restitution_speed_dependence);
  EXPECT_EQ(p.restitution_speed_dependence->knee_speed_mps, 2.2);
  EXPECT_EQ(p.restitution_speed_dependence->falloff_exponent, 0.3);
  writeMathavan2010(read, &echo);
  EXPECT_EQ(echo[kRestitutionSpeedDependenceKey], group[kRestitutionSpeedDependenceKey]);
  const nlohmann::json extra = {
      {kRestitutionSpeedDependenceKey, {{"knee_speed_mps", 2.2}, {"falloff_exponent", 0.3}, {"p", 1}}}};
  const JsonReader bad(extra, "t.json", "physics.cushion");
  EXPECT_MENTIONS(invalidArgumentMessage([&] { readMathavan2010(ModelDefaults{}, &bad); }),
                  "t.json: physics.cushion.restitution_speed_dependence.p");
}

TEST(CushionMathavan2010, AWrongTypeIsRefusedNamingTheKey) {
  const nlohmann::json group = {{"friction", "high"}};
  const JsonReader reader(group, "t.json", "physics.cushion");
  EXPECT_MENTIONS(invalidArgumentMessage([&] { readMathavan2010(ModelDefaults{}, &reader); }),
                  "t.json: physics.cushion.friction = \"high\"");
}

}  // namespace
}  // namespace baize::engine
