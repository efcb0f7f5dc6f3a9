#include "engine/play/random_shots.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "engine/io/scene.h"
#include "engine/io/table.h"

namespace baize::engine {
namespace {

// Bit-for-bit results, pinned over the shipped scenes and the benches' 3000 random single shots:
// every event (time, kind, balls, contact, the states before and after), every final state and
// each shot's end. A change of code that keeps the physics keeps these two numbers; a change of the
// physics changes them, and the new values (printed on failure) are pinned again with the reason.
constexpr std::uint64_t kPinnedShippedScenesHash = 14114166968737282780ULL;
constexpr std::uint64_t kPinnedWithRandomShotsHash = 15494948409772514452ULL;
constexpr int kRandomShots = 3000;

// FNV-1a over the bytes of a run's results.
class ResultHash {
 public:
  void add(const SceneRun& run) {
    for (const Event& e : run.result.events) {
      addDouble(e.time_s);
      addLong(static_cast<int>(e.kind));
      addLong(e.ball);
      addLong(e.other);
      addLong(e.index);
      for (const physics::BallState& s : e.before) addState(s);
      for (const physics::BallState& s : e.after) addState(s);
    }
    for (const BallRecord& b : run.result.final_balls) {
      addState(b.state);
      addLong(b.pocketed);
      addLong(b.pocket);
    }
    addDouble(run.result.end_time_s);
  }
  std::uint64_t value() const { return hash_; }

 private:
  void addBytes(const void* data, std::size_t size) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t k = 0; k < size; ++k) {
      hash_ ^= bytes[k];
      hash_ *= 1099511628211ULL;
    }
  }
  void addDouble(double d) { addBytes(&d, sizeof d); }
  void addLong(long v) { addBytes(&v, sizeof v); }
  void addState(const physics::BallState& s) {
    for (int k = 0; k < 2; ++k) addDouble(s.position[k]);
    for (int k = 0; k < 3; ++k) {
      addDouble(s.velocity[k]);
      addDouble(s.angular_velocity[k]);
    }
  }
  std::uint64_t hash_ = 1469598103934665603ULL;
};

TEST(RandomShots, ResultsArePinnedBitForBit) {
  std::vector<std::filesystem::path> files;
  for (const auto& f : std::filesystem::directory_iterator(assetsDirectory() + "/scenes"))
    files.push_back(f.path());
  std::sort(files.begin(), files.end());
  ResultHash hash;
  for (const auto& f : files) hash.add(runScene(loadScene(f.string())));
  EXPECT_EQ(hash.value(), kPinnedShippedScenesHash) << "new hash: " << hash.value() << "ULL";
  const std::vector<Scene> shots = randomSingleShots(kRandomShots);
  ASSERT_EQ(shots.size(), static_cast<std::size_t>(kRandomShots));
  for (const Scene& shot : shots) hash.add(runScene(shot));
  EXPECT_EQ(hash.value(), kPinnedWithRandomShotsHash) << "new hash: " << hash.value() << "ULL";
}

// The first shots of a set are the same whatever its size (a bench of 20 and one of 3000 share
// them), and every shot is a single cue ball and object ball on the 9 ft table.
TEST(RandomShots, TheFirstShotsAreTheSameWhateverTheCount) {
  const std::vector<Scene> few = randomSingleShots(20), many = randomSingleShots(200);
  for (std::size_t k = 0; k < few.size(); ++k) {
    ASSERT_EQ(few[k].balls.size(), 2u);
    EXPECT_EQ(few[k].balls[0].position_m, many[k].balls[0].position_m) << "shot " << k;
    EXPECT_EQ(few[k].balls[1].position_m, many[k].balls[1].position_m) << "shot " << k;
    EXPECT_EQ(few[k].shot.speed_mps, many[k].shot.speed_mps) << "shot " << k;
    EXPECT_EQ(few[k].table.name, "pool-9ft");
  }
}

// Every ball starts where a scene file could put it: on the table, the two apart, and in no
// pocket. The corner pockets' capture circles do reach between the rails (uniform points land
// there), so the draw has to refuse such places.
TEST(RandomShots, EveryBallStartsWhereASceneFileCouldPutIt) {
  const Scene base = nineFootPoolScene();
  const double R = 0.028575;  // the pool set's radius, m
  const double x = base.table.length_m / 2 - R, y = base.table.width_m / 2 - R;
  int uniform_points_in_a_pocket = 0;
  for (int i = 0; i <= 200; ++i) {
    for (int j = 0; j <= 100; ++j) {
      const Eigen::Vector2d p(-x + 2 * x * i / 200.0, -y + 2 * y * j / 100.0);
      uniform_points_in_a_pocket += inCaptureCircle(base.table, p) ? 1 : 0;
    }
  }
  EXPECT_GT(uniform_points_in_a_pocket, 0);

  for (const Scene& shot : randomSingleShots(20000, 2026)) {
    EXPECT_NEAR(shot.ball_set.radius_m, R, 1e-12);
    for (const PlacedBall& b : shot.balls) {
      EXPECT_LE(std::abs(b.position_m.x()), x);
      EXPECT_LE(std::abs(b.position_m.y()), y);
      EXPECT_FALSE(inCaptureCircle(shot.table, b.position_m)) << b.position_m.transpose();
      EXPECT_FALSE(pastBothDeepEnds(shot.table, b.position_m)) << b.position_m.transpose();
    }
    EXPECT_GE((shot.balls[0].position_m - shot.balls[1].position_m).norm(), 2 * R);
  }
}

}  // namespace
}  // namespace baize::engine
