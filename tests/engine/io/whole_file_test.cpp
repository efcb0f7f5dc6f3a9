#include "engine/io/whole_file.h"

#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace baize::engine {
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
  // A dangling link: the file it would name, in the link's folder.
  fs::create_symlink("missing.json", folder_ / "dangling.json");
  const fs::path named = wholeFileTarget((folder_ / "dangling.json").string()).path;
  EXPECT_EQ(named.filename(), "missing.json");
  EXPECT_TRUE(fs::equivalent(named.parent_path(), folder_)) << named;
}

// A relative link inside a linked folder counts ".." from where the folder really is (taking the
// path's text, d/.. cancelled out and the write went to the wrong folder).
TEST_F(WholeFileTest, ARelativeLinkInALinkedFolderIsReadFromTheRealFolder) {
  fs::create_directories(folder_ / "real" / "sub");
  fs::create_directory_symlink(folder_ / "real" / "sub", folder_ / "d");
  fs::create_symlink("../t.json", folder_ / "real" / "sub" / "x.json");
  const fs::path named = wholeFileTarget((folder_ / "d" / "x.json").string()).path;
  std::ofstream(named) << "written";
  EXPECT_TRUE(fs::exists(folder_ / "real" / "t.json")) << named;
  EXPECT_FALSE(fs::exists(folder_ / "t.json")) << named;
}

TEST_F(WholeFileTest, ALoopOfLinksIsRefused) {
  fs::create_symlink("b", folder_ / "a");
  fs::create_symlink("a", folder_ / "b");
  try {
    wholeFileTarget((folder_ / "a").string());
    ADD_FAILURE() << "a loop was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "it is a loop of symbolic links");
  }
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(folder_ / "a")));
}

TEST_F(WholeFileTest, DevicesAndPipesAreWrittenStraight) {
  const WholeFileTarget null_device = wholeFileTarget("/dev/null");
  EXPECT_TRUE(null_device.stream);
  EXPECT_EQ(null_device.path, "/dev/null");
  // A named pipe: refused while no program reads it (opening it would wait forever), written
  // straight once one does.
  const fs::path fifo = folder_ / "pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_THROW(wholeFileTarget(fifo.string()), std::invalid_argument);
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  EXPECT_TRUE(wholeFileTarget(fifo.string()).stream);
  ::close(reader);
  // An open descriptor by its /proc name (/dev/stdout is one): written straight, whatever it is.
  const int descriptor = ::open((folder_ / "log").c_str(), O_WRONLY | O_CREAT, 0600);
  ASSERT_GE(descriptor, 0);
  const std::string by_descriptor = "/dev/fd/" + std::to_string(descriptor);
  const WholeFileTarget target = wholeFileTarget(by_descriptor);
  EXPECT_TRUE(target.stream);
  EXPECT_EQ(target.path, by_descriptor);
  ::close(descriptor);
}

TEST_F(WholeFileTest, ADirectoryIsRefused) {
  EXPECT_THROW(wholeFileTarget(folder_.string()), std::invalid_argument);
  fs::create_directory_symlink(folder_, folder_ / "to_dir");
  EXPECT_THROW(wholeFileTarget((folder_ / "to_dir").string()), std::invalid_argument);
}

}  // namespace
}  // namespace baize::engine
