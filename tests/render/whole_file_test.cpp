#include "render/whole_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace baize::render {
namespace {

namespace fs = std::filesystem;

class WholeFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = fs::temp_directory_path() /
              ("baize_whole_file_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
               "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(folder_);
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }
  fs::path folder_;
};

TEST_F(WholeFileTest, AFileNewOrOldIsReplacedThroughATemporary) {
  const std::string fresh = (folder_ / "new.png").string();
  WholeFileTarget target = wholeFileTarget(fresh);
  EXPECT_EQ(target.path, fresh);
  EXPECT_FALSE(target.stream);
  EXPECT_EQ(temporaryFor(target), fresh + ".tmp");
  std::ofstream(fresh) << "old";
  target = wholeFileTarget(fresh);
  EXPECT_EQ(target.path, fresh);
  EXPECT_FALSE(target.stream);
}

TEST_F(WholeFileTest, ASymbolicLinkNamesTheFileToReplace) {
  const fs::path file = folder_ / "real.json";
  std::ofstream(file) << "old";
  fs::create_symlink("real.json", folder_ / "link.json");
  fs::create_symlink("link.json", folder_ / "link2.json");  // a chain
  for (const char* name : {"link.json", "link2.json"}) {
    const WholeFileTarget target = wholeFileTarget((folder_ / name).string());
    EXPECT_TRUE(fs::equivalent(target.path, file)) << name << ": " << target.path;
    EXPECT_FALSE(target.stream) << name;
  }
  // A dangling link: the file it would name.
  fs::create_symlink("missing.json", folder_ / "dangling.json");
  EXPECT_EQ(fs::path(wholeFileTarget((folder_ / "dangling.json").string()).path).filename(),
            "missing.json");
}

TEST_F(WholeFileTest, DevicesAndPipesAreWrittenStraight) {
  const WholeFileTarget null_device = wholeFileTarget("/dev/null");
  EXPECT_TRUE(null_device.stream);
  EXPECT_EQ(null_device.path, "/dev/null");
  const fs::path fifo = folder_ / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_TRUE(wholeFileTarget(fifo.string()).stream);
}

TEST_F(WholeFileTest, ADirectoryIsRefused) {
  EXPECT_THROW(wholeFileTarget(folder_.string()), std::invalid_argument);
  fs::create_directory_symlink(folder_, folder_ / "to_dir");
  EXPECT_THROW(wholeFileTarget((folder_ / "to_dir").string()), std::invalid_argument);
}

}  // namespace
}  // namespace baize::render
