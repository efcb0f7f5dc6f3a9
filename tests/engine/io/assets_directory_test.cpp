#include "engine/io/assets_directory.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace baize::engine {
namespace {

namespace fs = std::filesystem;

// A fresh folder under the system's temporary one, removed at the end of the test.
class TempTree : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() /
            ("baize-assets-test-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
             "-" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  void TearDown() override { fs::remove_all(root_); }
  fs::path root_;
};

TEST_F(TempTree, FindsTheNearestShareBaizeAboveTheProgram) {
  fs::create_directories(root_ / "prefix/share/baize/tables");
  fs::create_directories(root_ / "prefix/lib/python3/dist-packages/baize");
  fs::create_directories(root_ / "prefix/bin");
  EXPECT_EQ(assetsDirectoryAbove((root_ / "prefix/bin").string()),
            (root_ / "prefix/share/baize").string());
  EXPECT_EQ(assetsDirectoryAbove((root_ / "prefix/lib/python3/dist-packages/baize").string()),
            (root_ / "prefix/share/baize").string());
}

TEST_F(TempTree, IgnoresAShareBaizeWithoutTables) {
  fs::create_directories(root_ / "prefix/share/baize/scenes");  // not an assets folder
  fs::create_directories(root_ / "prefix/bin");
  EXPECT_EQ(assetsDirectoryAbove((root_ / "prefix/bin").string()), "");
}

TEST_F(TempTree, ClimbsOnlyAFewFolders) {
  fs::create_directories(root_ / "share/baize/tables");
  const fs::path deep = root_ / "a/b/c/d/e/f/g/h";
  fs::create_directories(deep);
  EXPECT_EQ(assetsDirectoryAbove((root_ / "a/b").string()), (root_ / "share/baize").string());
  EXPECT_EQ(assetsDirectoryAbove(deep.string()), "");
}

// Each test runs in a process of its own (ctest), so the variable is read fresh here.
TEST_F(TempTree, TheEnvironmentVariableNamesTheFolder) {
  fs::create_directories(root_ / "elsewhere/tables");
  ASSERT_EQ(setenv(kDataDirectoryVariable, (root_ / "elsewhere").c_str(), 1), 0);
  EXPECT_EQ(assetsDirectory(), (root_ / "elsewhere").string());
  unsetenv(kDataDirectoryVariable);
}

TEST_F(TempTree, AVariableNamingNoAssetsIsRefusedByName) {
  const std::string nowhere = (root_ / "nowhere").string();
  ASSERT_EQ(setenv(kDataDirectoryVariable, nowhere.c_str(), 1), 0);
  try {
    assetsDirectory();
    ADD_FAILURE() << "a folder with no tables/ was accepted";
  } catch (const std::runtime_error& refused) {
    EXPECT_NE(std::string(refused.what()).find(nowhere), std::string::npos) << refused.what();
    EXPECT_NE(std::string(refused.what()).find(kDataDirectoryVariable), std::string::npos);
  }
  unsetenv(kDataDirectoryVariable);
}

TEST(AssetsDirectory, TheBuildTreeFindsTheShippedTables) {
  unsetenv(kDataDirectoryVariable);
  EXPECT_TRUE(fs::is_regular_file(fs::path(assetsDirectory()) / "tables/pool-9ft.json"));
}

}  // namespace
}  // namespace baize::engine
