#include "engine/sim/cushion_impact_worker.h"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>

#include "engine/io/scene.h"
#include "engine/io/table.h"

namespace baize::engine {
namespace {

// The threads of this process, from /proc (Linux).
long threadCount() {
  long count = 0;
  for ([[maybe_unused]] const auto& task : std::filesystem::directory_iterator("/proc/self/task"))
    ++count;
  return count;
}

// The kernel lists a joined thread in /proc for a moment after pthread_join returns: a count that
// should drop is read again for up to this long.
constexpr auto kThreadExitGrace = std::chrono::seconds(2);

// The thread count once it has settled to `expected` (or what it is after kThreadExitGrace).
long threadCountSettled(long expected) {
  const auto start = std::chrono::steady_clock::now();
  long count = threadCount();
  while (count != expected && std::chrono::steady_clock::now() - start < kThreadExitGrace) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    count = threadCount();
  }
  return count;
}

Scene shippedScene(const std::string& name) {
  return loadScene(assetsDirectory() + "/scenes/" + name + ".json");
}

// No hidden threads: shots run on the caller's thread alone unless it hands a worker over, and a
// worker is one thread, gone with it.
TEST(CushionImpactWorker, ShotsStartNoThreadAndAWorkerIsOneThreadTheCallerOwns) {
  const long before = threadCount();
  for (int shot = 0; shot < 20; ++shot) runScene(shippedScene("9-ball-break"));
  EXPECT_EQ(threadCount(), before);
  {
    CushionImpactWorker worker;
    EXPECT_EQ(threadCount(), before + 1);
    worker.wake();
    for (int shot = 0; shot < 5; ++shot) runScene(shippedScene("9-ball-break"), false, &worker);
    EXPECT_EQ(threadCount(), before + 1);
  }
  EXPECT_EQ(threadCountSettled(before), before);
}

}  // namespace
}  // namespace baize::engine
