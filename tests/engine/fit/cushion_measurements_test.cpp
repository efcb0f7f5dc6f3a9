#include "engine/fit/cushion_measurements.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace baize::engine {
namespace {

std::string fileWith(const std::string& text) {
  const std::string path =
      (std::filesystem::temp_directory_path() /
       ("baize_measurements_" + std::to_string(std::hash<std::string>{}(text)) + ".csv"))
          .string();
  std::ofstream(path) << text;
  return path;
}

// The error, which must name every piece of `expected`.
void expectRefused(const std::string& text, std::initializer_list<const char*> expected) {
  const std::string path = fileWith(text);
  try {
    readCushionMeasurements(path);
    ADD_FAILURE() << "accepted:\n" << text;
  } catch (const std::invalid_argument& refused) {
    for (const char* piece : expected) {
      EXPECT_NE(std::string(refused.what()).find(piece), std::string::npos)
          << "'" << piece << "' not in: " << refused.what();
    }
  }
  std::remove(path.c_str());
}

TEST(CushionMeasurements, ReadsOptionalColumnsWithTheirDefaults) {
  const std::string path = fileWith(
      "speed_mps,angle_deg,rebound_speed_mps,rebound_angle_deg\n1,90,0.7,\n1.2,45,0.9,40\n");
  const auto data = readCushionMeasurements(path);
  ASSERT_EQ(data.size(), 2u);
  EXPECT_EQ(data[0].line, 2);
  EXPECT_EQ(data[0].topspin_k, 1);
  EXPECT_EQ(data[0].sidespin_k, 0);
  EXPECT_FALSE(data[0].rebound_angle_deg);
  EXPECT_EQ(data[1].line, 3);
  EXPECT_EQ(*data[1].rebound_angle_deg, 40);
  std::remove(path.c_str());
}

TEST(CushionMeasurements, ReadsSpins) {
  const std::string path = fileWith(
      "speed_mps,angle_deg,topspin,sidespin,rebound_speed_mps\n1,60,0,-1.5,0.8\n");
  const auto data = readCushionMeasurements(path);
  EXPECT_EQ(data[0].topspin_k, 0);
  EXPECT_EQ(data[0].sidespin_k, -1.5);
  std::remove(path.c_str());
}

TEST(CushionMeasurements, RefusesBadInputNamingLineAndColumn) {
  expectRefused("speed_mps,rebound_speed_mps\n1,0.7\n", {"no column 'angle_deg'"});
  expectRefused("speed_mps,angle_deg,rebound_speed_mps,topspn\n1,90,0.7,1\n",
                {"line 1", "column 'topspn'"});
  expectRefused("speed_mps,angle_deg,rebound_speed_mps\n1,90,0.7\n1,9O,0.7\n",
                {"line 3", "column angle_deg", "9O", "number"});
  expectRefused("speed_mps,angle_deg,rebound_speed_mps\n-1,90,0.7\n",
                {"line 2", "column speed_mps = -1", "> 0"});
  expectRefused("speed_mps,angle_deg,rebound_speed_mps\n1,180,0.7\n",
                {"line 2", "column angle_deg = 180", "between 0 and 180"});
  expectRefused("speed_mps,angle_deg,rebound_speed_mps\n1,0,0.7\n", {"column angle_deg = 0"});
  expectRefused("speed_mps,angle_deg,rebound_speed_mps\n1,90,0\n",
                {"line 2", "column rebound_speed_mps = 0"});
  // A rolling ball carries sqrt(1.4) V0 of energy at most.
  expectRefused("speed_mps,angle_deg,rebound_speed_mps\n1,90,1.2\n",
                {"line 2", "column rebound_speed_mps = 1.2", "energy"});
  expectRefused("speed_mps,angle_deg,rebound_speed_mps,rebound_angle_deg\n1,90,0.7,190\n",
                {"line 2", "column rebound_angle_deg = 190"});
  expectRefused("speed_mps,angle_deg,rebound_speed_mps\n", {"no measurements"});
}

}  // namespace
}  // namespace baize::engine
